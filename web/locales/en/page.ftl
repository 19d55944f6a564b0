# The page's labels, buttons, notes and messages, by the part of the page that shows them.
# Numbers come in variables, already written in the language's way.

## The header

language-menu = Language

## Loading the lessons

# $reason is the browser's reason, in its words.
lessons-not-loaded = The lessons’ texts could not be loaded: { $reason }. Open the Lessons tab again to retry.
