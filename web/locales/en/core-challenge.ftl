# The core's messages about design challenges and their grading: why a challenge or submission
# link was refused, the task in words, the verdict on each criterion, and the grading of a class.
# The CLI says them in English from this file; the page in the reader's language; the grades' CSV
# holds them in English. Keys, fields, figures and settings (c=1, allow.FIELD, need.FIGURE=OP,
# seeds:A..B, try.FIELD, mean_nis, load.torque = 0) are the link's own words: keep them as they
# are. Quoted input keeps its quotes.

## A challenge or submission link refused

# $key is the link's key (title, vary, try.k1…), $value the text it holds.
challenge-not-percent-encoded = field '{ $key }' = '{ $value }': not valid percent-encoded UTF-8
challenge-too-long = the challenge is { $bytes } bytes long, more than the { $max } bytes ({ $kib } KiB) allowed
# $names lists the built-in challenges' names.
challenge-unknown = '{ $name }' is neither a challenge link nor a built-in challenge ({ $names })
challenge-unsupported-version = field 'c' = '{ $value }': unsupported challenge version, allowed: { $version }
# $fields lists the keys a challenge link may hold.
challenge-unknown-key = field '{ $key }' is not a challenge field ({ $fields })
challenge-missing = field '{ $key }' is missing
# $name is the built-in challenge's name.
challenge-builtin-extra = field '{ $key }' cannot follow challenge={ $name }: a built-in challenge's link holds only challenge=NAME and the student's try.FIELD parts
# $stray is the characters written before c=; $count how many there are.
challenge-stray = the link starts with the stray { $count ->
        [one] character
       *[other] characters
    } '{ $stray }' before its c={ $version }: remove { $count ->
        [one] it
       *[other] them
    }
challenge-version-missing = field 'c' is missing (a challenge starts with c={ $version })
challenge-title-too-long = field 'title' is { $chars } characters long, more than the { $max } allowed
# $error says why the base scenario was refused (a scenario-* message).
challenge-bad-base = field 'base': { $error }
challenge-no-criteria = no criteria: add at least one need.FIGURE=OP
challenge-too-many-criteria = { $count } criteria, more than the { $max } allowed
challenge-vary-unused = field 'vary': no criterion uses the variants (name the criteria's figures in robust=)
challenge-robust-without-vary = field 'robust': there are no variants (add vary=)
# $key is allow.FIELD; $field the scenario field it names.
challenge-allow-unknown-field = field '{ $key }': '{ $field }' is not a scenario field
challenge-allow-formula = field '{ $key }' = '{ $value }': a step's law is allowed as allow.{ $field }=formula
challenge-allow-range = field '{ $key }' = '{ $value }': expected LO..HI, two numbers with LO ≤ HI
# $error says why an end of the range is no value of the field (a scenario-* message).
challenge-allow-refused = field '{ $key }' = '{ $value }': { $error }
# $options lists the field's names, separated by |.
challenge-allow-choice = field '{ $key }' = '{ $value }': expected distinct names from { $options }, separated by |
# $key is need.FIGURE; $figures lists the figures a criterion may name.
challenge-need-unknown-figure = field '{ $key }': '{ $figure }' is not a figure ({ $figures })
challenge-need-band = field '{ $key }' = 'band': only mean_nis has a band
challenge-need-op = field '{ $key }' = '{ $value }': expected max:B, min:B, abs:B or band
challenge-need-no-load-step = field '{ $key }': the base has no load step (load.torque = 0, or a load table instead)
challenge-vary-seeds = field 'vary' = '{ $value }': expected seeds:A..B, whole numbers with A ≤ B ≤ { $max_seed } and at most { $max } seeds
challenge-vary-too-many = field 'vary': { $count } variants, more than the { $max } allowed
# $number counts the variants from 1; $error says what is wrong with it (a scenario-* message).
challenge-vary-variant-refused = field 'vary', variant { $number }: { $error }
challenge-vary-variant-empty = field 'vary', variant { $number } is empty
# $overrides is the variant's settings (seed=2); $error says why they do not apply.
challenge-variant-refused = variant '{ $overrides }': { $error }
# $value is the robust= list, $figure the name in it that is not a criterion's.
challenge-robust-unknown = field 'robust' = '{ $value }': '{ $figure }' is not the figure of a criterion (or is named twice)
challenge-is-submission = field 'try.{ $key }': this is a submission, not a challenge (grade it against its challenge)
challenge-another = the submission belongs to another challenge (its challenge text differs)
challenge-try-not-allowed = field '{ $field }' is not allowed
challenge-try-not-number = field 'try.{ $field }' = '{ $value }': not a number
# $setting is the student's setting (k1=6000), $range the allowed one (300..5000).
challenge-try-outside = { $setting } is outside { $range }
# $options lists the allowed names, separated by |.
challenge-try-not-option = { $setting } is not one of { $options }
challenge-compose-range-and-options = field '{ $key }': give LO and HI (a range) or options (choices), not both
challenge-judge-runs = the challenge has { $runs ->
        [one] { $runs } run
       *[other] { $runs } runs
    } (nominal and { $variants ->
        [one] { $variants } variant
       *[other] { $variants } variants
    }), { $measured } measured

## The task in words

challenge-untitled = Design challenge
# The challenge's title, as its author wrote it.
challenge-title = { $title }
# $base is the scenario string.
challenge-brief-start = Start from the scenario { $base }
challenge-brief-nothing-allowed = Nothing may be changed: the base is judged as it is.
challenge-brief-allowed = You may change only:
# One field the student may change: $field its name (padded to a column), $range what it may be
# (a challenge-brief-range, -one-of or -formula message), $now the base's value, $doc the field
# in words.
challenge-brief-allow = { $field } { $range } (now { $now }) — { $doc }
# $hi has its unit, if any.
challenge-brief-range = { $lo } to { $hi }
# $options lists the names.
challenge-brief-one-of = one of { $options }
challenge-brief-formula = a formula of your own
challenge-brief-formula-unit = a formula of your own, in { $unit }
challenge-brief-needs = Your design must meet:
# One criterion: $number counts them from 1, $label is the figure in words, $figure its name,
# $bound a challenge-brief-at-most, -at-least, -within or -band message; $settled is yes for a
# final value, which must have settled; $robust is yes when it must hold on every variant too.
challenge-brief-need = { $number }. { $label } ({ $figure }): { $bound }{ $settled ->
        [yes] , and settled by the end of the run
       *[no] {""}
    }{ $robust ->
        [yes] {" "}— on the nominal run and on every variant
       *[no] {""}
    }
# $bound has its unit, if any.
challenge-brief-at-most = at most { $bound }
challenge-brief-at-least = at least { $bound }
challenge-brief-within = within ±{ $bound }
challenge-brief-band = inside the 95 % band of a consistent filter (mean_nis_low to mean_nis_high)
# $first and $last are the first and the last noise seed (seed=2…).
challenge-brief-variants-seeds = Variants (applied on top of your settings; the worst run counts): noise seeds { $first } to { $last }
# $overrides lists each variant's settings, separated by semicolons.
challenge-brief-variants = Variants (applied on top of your settings; the worst run counts): { $overrides }
challenge-brief-load-recovery = Load recovery time: the time from the load step (t = { $time } s) until |ω − ω_d| stays within max(1 % of |ω_d| at the step, 0.5 rad/s) to the end of the run (here { $band } rad/s at ω_d = { $speed } rad/s); not recovered if it is still outside at the end.
challenge-brief-settled = A final value counts only if it has settled: a value still changing over the last tenth of the run fails.
# A number and its unit: "0.004 s".
challenge-quantity = { $value } { $unit }

## A criterion's bound and why it fails

# $bound has its unit, if any: "≤ 0.004 s".
challenge-bound-max = ≤ { $bound }
challenge-bound-min = ≥ { $bound }
challenge-bound-abs = |·| ≤ { $bound }
challenge-bound-band = inside its 95 % band
# $failure says why the run failed (in English until the simulation's messages are translated).
challenge-run-unfinished = the run did not finish
challenge-reason-run-failed = run failed: { $failure }
# $cause says why the figure is not a number (a warning's cause of core-run.ftl or core-formula.ftl).
challenge-reason-not-finite = { $cause }
challenge-reason-before-load-step = not measured: the run ends before the load step
challenge-reason-not-measured = not measured on this run (e.g. a step that never settles within 2 %)
challenge-reason-no-band = not measured: no NIS band on this run
challenge-reason-above-bound = above the bound
challenge-reason-below-bound = below the bound
challenge-reason-beyond-bound = beyond the bound
challenge-reason-below-band = below the band
challenge-reason-above-band = above the band
challenge-reason-not-recovered = not recovered by the end of the run
challenge-reason-still-changing = still changing

## A class's grading: each submission's status (in the grades' CSV too) and the class's file

grade-row-ok = ok
# $reason says why the link is not a well-formed submission.
grade-row-malformed = malformed: { $reason }
# $reason names the field the student set that is not allowed, or out of its range.
grade-row-refused = refused: { $reason }
grade-row-another = another challenge
# $reason says why a run failed (in English until the simulation's messages are translated).
grade-row-run-failed = run failed: { $reason }
grade-internal-error = internal error
# $encoding is the name of the encoding the file was read in (UTF-8, windows-1252…).
grade-line-undecoded = line { $line } is not valid { $encoding }
grade-line-unclosed = line { $line }: a quoted field is not closed by the end of the file
grade-line-fields = line { $line } has { $fields ->
        [one] { $fields } field
       *[other] { $fields } fields
    }, the header { $header }
grade-no-link = no link
# $error says why the challenge was refused.
grade-challenge-refused = challenge: { $error }
grade-file-not-text = the file is not text (it holds NUL bytes: a spreadsheet or a document?); save it as a text file of links, one a line, or as CSV
grade-file-utf16 = the file is UTF-16 without a byte-order mark; save it as UTF-8
grade-file-header-undecoded = line { $line }, the CSV header, is not valid { $encoding }
# $columns lists the file's column headers, each quoted.
grade-file-no-link-column = no column of links in this CSV export (its columns: { $columns }); head the column of links 'link'
grade-file-links-everywhere = the columns { $columns } all hold links; head the one to grade 'link'
grade-file-link-headers = the columns { $columns } are all headed as links; keep one

## Resuming an interrupted grading (imlab grade --resume): why its earlier output is refused

grade-resume-not-utf8 = it is not UTF-8 text, so not the grades of this class
# $header is the CSV header line this grading writes.
grade-resume-header = its first line is not this grading's header '{ $header }': it holds the grades of another challenge or class file
grade-resume-too-many-rows = it holds more rows than the class file has submissions ({ $rows })
grade-resume-row = its row { $row } is not that of line { $line } ('{ $link }') of the class file: it holds the grades of another class file
# $what is one of the grade-kept-* messages.
grade-kept-differs = its row { $row } (line { $line } of the class file) is not what grading it again gives: { $what }; it was edited after its grading, or graded by another version of imlab
# $column is the CSV column's name (status, settling_time_pass…).
grade-kept-cell = its { $column } is '{ $found }', not '{ $expected }'
grade-kept-extra = it has '{ $extra }' after its last column
grade-kept-short = it lacks its columns from { $column } on
