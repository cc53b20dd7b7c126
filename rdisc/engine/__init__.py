"""The engine: the run-time semantics of RDIS, small modules that every generated driver carries."""
