"""Highlighting of RDIS text: the words and token patterns of the grammar (vocabulary.py, written
by writer.py), a TextMate grammar made of them (textmate.py, written into editors/vscode) and a
Pygments lexer (pygments_lexer.py)."""
