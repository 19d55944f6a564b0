# The core's refusals of a formula, and why a law's distance from its designed dynamics is not a
# number: said as a link is read or a run ends, with the page's first messages.
# $reason is one of the formula-* messages below; $at counts the formula's characters from 1.
formula-at = at character { $at }: { $reason }
# $written is the number as typed.
formula-not-a-number = '{ $written }' is not a number
formula-number-too-large = '{ $written }' is too large for a number
# $char is the character typed.
formula-not-in-language = '{ $char }' is not part of the language (+ − * / ^, parentheses, names, numbers)
formula-division-by-zero = division by zero
formula-nests-too-deep = the formula nests deeper than { $max } levels here
formula-ends-early = the formula ends where a number, a name or '(' is expected
formula-never-closed = this '(' is never closed
formula-expected-close = expected ')' or an operator here
# $op is the operator typed (* / ^ ) or ,), a product written · or × given as *.
formula-misplaced-operator = '{ $op }' where a number, a name or '(' is expected
# $name is the name typed; $functions lists the functions' names.
formula-no-function = no function '{ $name }': the functions are { $functions }
# $name is a function's name: "in sqrt( )".
formula-expected-argument-end = expected ',' or ')' in { $name }( )
# $arity is how many arguments the function takes, $given how many it was given.
formula-arguments = { $name } takes { $arity } { $arity ->
        [one] argument
       *[other] arguments
    }, not { $given }
# $from is the step whose law gives the name.
formula-later-name = '{ $name }' is not known in step { $step }: it comes from step { $from }'s law
formula-is-function = '{ $name }' is a function: write { $name }( )
# $name is x1, the true speed.
formula-true-speed = '{ $name }' is the true speed, which a sensorless controller does not have: write its estimate x1h
# $name is x4 or x5, a true rotor flux.
formula-true-flux = '{ $name }' is a true rotor flux, which no drive measures: write its estimate x4h or x5h
# $name is xt1, xt4 or xt5.
formula-unmeasured-error = '{ $name }' is an estimation error of an unmeasured state, which a sensorless controller cannot know: the paper leaves such terms in d̃2 and d̃4, which the robust term (robust·h²/(4ε)·z) is designed against
formula-unknown-name = unknown name '{ $name }' (see the list of names)
formula-too-long = the formula has { $length } characters, more than the { $max } allowed
formula-empty = the formula is empty
formula-unopened = this ')' has no '(' before it
formula-expected-operator = expected an operator here (a product is written with *)
formula-too-many-operations = the formula takes { $operations } operations, more than the { $max } allowed
formula-too-deep = the formula nests { $depth } values deep, more than the { $max } allowed: write it with fewer nested parentheses
# $error is a formula-* message, with its place.
law-refused = law.v{ $step }: { $error }
law-no-such-step = step { $step }: the steps are 1 to 4
law-none = the scenario has no law of its own: give law.v1, law.v2, law.v3 or law.v4
law-no-own-law = the step has no law of its own
law-not-designed-one = the law does not give its designed dynamics
# $failed of the scenario's $laws own laws.
law-not-designed-some = { $failed ->
        [one] { $failed } of { $laws } laws does not give its designed dynamics
       *[other] { $failed } of { $laws } laws do not give their designed dynamics
    }
law-never-runs = your { $before } gives no finite value at any of the { $draws } drawn states, so step { $step } never runs
law-no-share = your { $output } ({ $unit }) differs from the { $output } that gives the designed dynamics where the paper's law is all but zero, by no finite share of its size
# $count of the $draws drawn states; $reads is none when the law reads no signal, else $names
# lists the names it reads with their values there (law-named-value).
law-differs-infinitely = your { $output } ({ $unit }) differs infinitely from the { $output } that gives the designed dynamics at { $count } of the { $draws } drawn states{ $reads ->
        [none] , reading no signal
       *[some] , e.g. at { $names }
    }
# As law-differs-infinitely; $value is what the law gives: inf, -inf or NaN.
law-not-finite = your { $output } ({ $unit }) is not a finite number at { $count } of the { $draws } drawn states: it gives { $value }{ $reads ->
        [none] , reading no signal
       *[some] {" "}at { $names }
    }
# A name a law reads and its value: "z1 = 0.25".
law-named-value = { $name } = { $value }
law-paper-zero = the paper’s law stayed at zero over the run while yours did not
