# The page's labels, buttons, notes and messages, by the part of the page that shows them.
# Numbers come in variables, already written in the language's way.

## The header

language-menu = Language
