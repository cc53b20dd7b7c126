"""`rdisc lsp`: the language server. Its modules each answer one kind of question about the
documents an editor has open (the index of names, hover, navigation, completion, symbols);
only `server` knows pygls, and nothing here is imported by `rdisc check`."""
