"""Test doubles shared by the test files (imported as `tests.support...`)."""
