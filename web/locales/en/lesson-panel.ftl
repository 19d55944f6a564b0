# The lessons' list and the lesson panel beside the plots.

## The list in the Lessons tab

# A lesson's card: its number and title ("1. The paper’s step response").
lesson-numbered-title = { $number }. { $title }
lesson-list-question = Question: { $question }
lesson-start = Start lesson { $number }

## The lesson panel

lesson-count = Lesson { $number } of { $count }
# $run is the lesson's scenario, as a link writes it (v=1&preset=step).
lesson-run = {" "}· run { $run }
lesson-look-head = What to look for
lesson-question-head = Question
lesson-hint = Hint
lesson-show-answer = Show answer (for the lecturer)
lesson-previous = ← Previous
lesson-next = Next →
lesson-close = Close lesson
# The button "Copy link to this lesson": presentation mode shows its first part only.
lesson-copy-link-short = Copy link
lesson-copy-link-rest = {" "}to this lesson
lesson-link-copied = Link copied: it opens this lesson and its run.
lesson-copy-this-link = Copy this link: { $link }
lesson-load-run = Load the lesson’s run
# $differences lists how the link's settings differ from the lesson's run, as the core writes it
# ("k1: 1200 → 600 1/s; duration: 6 → 0.3 s").
lesson-own-settings = This link holds settings of its own, and they are shown as it has them, not the lesson’s run: { $differences }. What the lesson says of its run need not hold for them.
