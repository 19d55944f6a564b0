# The Analysis, Lessons and Challenge tabs' own words, and the marks of a result of an earlier
# scenario: they come with the rest of the page's messages, after the first plot (web/l10n/l10n.js).

map-heading = Model-error map
# The map's introduction is cut around three pieces of code: plant.*, model.* and an example
# axis, plant.rr=-10%..+10%:11. map-intro-start stands before "plant.*", map-intro-model between
# "plant.*" and "model.*", map-intro-axes between "model.*" and the example, map-intro-example after it.
map-intro-start = How far does a result hold when the motor is not what the EKF and the controller assume? Runs the current scenario over one or two motor (
map-intro-model = ) or model (
map-intro-axes = ) parameters, each value with every seed, and shows each figure's median and range over the seeds. Write an axis as KEY=LO..HI:N, in values or as relative errors against the other side:{ " " }
map-intro-example = { " " }is the motor's rotor resistance from 10 % below to 10 % above the model's. Any other numeric field, such as a gain (k1=-20%..+20%:5), the EKF's tuning or the flux target, is read against the scenario's own value.
map-axis = axis
map-second-axis = second axis (optional)
map-seeds = seeds
map-run-button = Run map
sweep-heading = Closed-loop frequency response
sweep-intro = Sweeps sinusoidal speed references ω_d = offset + A·sin(2πft) over the current scenario, fits the fundamental of ω (and of the controller's speed estimate) after the first half of each run, and reads off the −3 dB bandwidth and the phase at 200 Hz. Keep A small enough that the voltages stay off the limit; the table reports the saturation. The classical IFOC needs an operating speed (its MRAS is blind near zero speed) and longer runs (its speed loop is 10 Hz).
# The sweep's fields: from … Hz, to … Hz, points, offset … rad/s, run length … s, workers.
sweep-from = from
sweep-to = to
sweep-points = points
sweep-offset = offset
sweep-run-length = run length
sweep-workers = workers
sweep-variants = variants
sweep-variant-euler = Euler EKF (paper)
sweep-variant-rk4 = RK4 EKF
sweep-variant-perfect = perfect observer
sweep-variant-delay = Euler EKF, one-sample delay
sweep-variant-ifoc = classical IFOC, torque feedforward
sweep-variant-ifocpi = classical IFOC, PI only
sweep-run-button = Run sweep
seeds-heading = Seed sweep
seeds-intro = Runs the current scenario with N noise seeds in parallel and shows, per sample, the mean and the min–max band of the speed error and the estimation error.
# Labels the number of seeds.
seeds-count = seeds
seeds-run-button = Run seeds
motor-heading = A motor of your own, from its nameplate and lab tests
lessons-heading = Lessons
lessons-intro = Each lesson loads a preset and runs it, and opens a lesson panel beside the plots with what to look for, the question, a hint and the answer. The figures above the plots answer most questions.
challenges-heading = Design challenges
challenges-intro = A challenge is a design task in a link: the student may change only some settings and passes when every criterion holds, on the nominal run and on its variants. The links below open the built-in ones; the Challenge tab composes new ones.
compose-heading = Compose a challenge
grade-heading = Grade a class
# The grading's introduction is cut around the command "imlab grade": grade-intro-start stands before it, grade-intro-end after it.
grade-intro-start = Grades every submission link of a class file against a challenge, in this browser: nothing leaves it. The class file is one link a line, or a course platform's CSV export with a column of links (its other columns, such as the student's name, are carried into the result). The CSV is the one{ " " }
grade-intro-end = { " " }writes for the same files, byte for byte. A cancelled or interrupted grading is kept in this browser until the next grading, and Grade goes on where it stopped.
grade-challenge-input =
    .placeholder = a built-in's name or a challenge link
grade-class-file = Class file
# Labels the menu of the figure the map shows.
map-figure = figure
map-progress =
    .aria-label = Map runs done
sweep-csv = CSV (first variant)
seeds-progress =
    .aria-label = Seed runs done
compose-fill = Fill from the current scenario
grade-challenge = Challenge
grade-paste = or paste the links, one a line
grade-run = Grade
grade-csv = Download CSV
grade-progress =
    .aria-label = Submissions graded
grade-table =
    .aria-label = Grades of the class
stale-map = This map is of an earlier scenario ({ $scenario }), not of the settings now. Press “Run map” to bring it up to date. Its CSV names the scenario it was run for.
stale-sweep = These Bode plots and this table are of an earlier scenario ({ $scenario }), not of the settings now. Press “Run sweep” to bring them up to date. Their CSV, which does not name its scenario, is off until then.
stale-seeds = These seed bands are of an earlier scenario ({ $scenario }), not of the settings now. Press “Run seeds” to bring them up to date. Their CSV, which does not name its scenario, is off until then.
stale-challenge = This verdict is of an earlier scenario ({ $scenario }), not of the settings now. Press “Run and check” to bring it up to date. “Copy submission link” copies the link of the settings it checked.
# The walkthrough's comparison of the EKF's predictors.
stale-compare = This comparison is of an earlier scenario ({ $scenario }), not of the settings now. Press “Run”, then the comparison’s button, to bring it up to date.
