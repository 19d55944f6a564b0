# The core's messages about a step's own law: why a formula was refused, and the verdict on a law
# against the error dynamics its step is designed to give. The CLI says them in English from this
# file; the page in the reader's language. Names (x1h, k1s1, v1, z2), functions (sqrt), formulas
# (ż1 = −k1·z1 + z2, a3·ω_d), settings (law.v1), the paper's equation numbers ((28)) and quoted
# input are the language's and the paper's own: keep them as they are. Quoted input keeps its
# quotes.

## A formula refused


## A step's own law refused or missing


## The verdict on a step's own law

# $designed is the step's designed error dynamics (ż1 = −k1·z1 + z2); $output the virtual control
# the law gives (v1); $own is yes when the step is judged on the student's own law of the step
# before, $before (v1 or v3); $worst how far the law is from it, relative to its size (2e-16);
# $draws how many states were drawn; $caveats is one of the law-caveat-* messages.
law-designed = Your step { $step } gives the designed dynamics { $designed }{ $own ->
        [yes] {" "}with your own { $before }: your { $output } equals the one that gives them
       *[no] : your { $output } equals the paper's
    } to { $worst } of its size at { $draws } drawn states and parameter values.{ $caveats }
# As law-designed; $unit is the unit of $output; $difference is law-difference or
# law-difference-unnamed.
law-not-designed = Your step { $step } does not give the designed dynamics { $designed }{ $own ->
        [yes] {" "}with your own { $before }: your { $output } ({ $unit }) differs from the one that gives them
       *[no] : your { $output } ({ $unit }) differs from the paper's
    } by up to { $worst } of its size at { $draws } drawn states. { $difference }{ $caveats }
# $cause is one of the law-never-runs … law-not-finite messages.
law-not-designed-because = Your step { $step } does not give the designed dynamics { $designed }: { $cause }.
law-cannot-judge = Your step { $step } cannot be judged: { $cause }.
# $finding is one of the law-term-*, law-mistake-*, law-scenario-values-only and law-rate-of-z
# messages.
law-difference = The difference: { $finding }.
law-difference-unnamed = The difference is not one term of the paper's law: compare your law with the step's derivation term by term.

## What a verdict adds after its sentence (each caveat starts with the space after the sentence)

law-caveat-none = {""}
# $names lists the names the student's law of the step before reads whose rates are not known.
law-caveat-unchained = {" "}Your { $before } reads { $names }, whose rate the loop does not have (it holds the voltage a later step chooses, or a derivative the loop lacks), so this step is judged on the paper's { $before }.
law-caveat-failed = {" "}Your { $before } gives no finite value at { $failed } of the { $draws } drawn states, which this step is not judged at.
# Both caveats: $unread is law-caveat-unchained, $failing law-caveat-failed.
law-caveat-both = { $unread }{ $failing }

## Why a law's distance from its designed dynamics is not a number


## What a wrong law gets wrong

# $term is a term of the paper's law with its sign (+a3·ω_d).
law-term = the term { $term }
# $part is a part of the term $term multiplied out.
law-term-part = the part { $part } of the term { $term }
# $label is law-term or law-term-part.
law-term-missing = { $label } of the paper's law is missing
law-term-wrong-sign = { $label } has the wrong sign
law-term-twice = { $label } is there twice
# $factor is how many times the paper's term the law has.
law-term-scaled = { $label } is { $factor } times what it should be
law-scenario-values-only = it equals the paper's law at this scenario's parameter values and gains only: a parameter or a gain is written as its number where the law needs its name
# The law is the paper's minus (or plus) $gain times the step's error $z (z1): $now is the rate its
# error then decays at, $meant the designed one.
law-rate-of-z = it is the paper's law { $sign ->
        [minus] minus
       *[plus] plus
    } { $gain }·{ $z }: with this scenario's parameters your { $z } decays at { $now } /s, not { $meant } /s; check the gain and the sign of your { $z } terms

## Slips students make, named when a law equals one

law-mistake-k1 = it has k1 where (28) has k1s1 = k1 − a3
law-mistake-a3-x1h = it has a3·x̂1 where (27) has a3·ω_d
law-mistake-k2 = it has k2 where (36) has k2s1 = k2 − a7 − a8: the −(a7 + a8)·z2 of ż2 is then left in
law-mistake-printed-dv1 = it takes v̇1 as printed in (31), with both of its typos: a3·ω_d where the derivative of a3·ω_d is a3·ω̇_d, and â2 where the derivative of â2 is its rate (0 for a known load)
law-mistake-printed-dv1-wd = it takes v̇1 as printed in (31), with a3·ω_d where the derivative of a3·ω_d is a3·ω̇_d
law-mistake-printed-dv1-a2 = it takes v̇1 as printed in (31), with â2 where the derivative of â2 is its rate (0 for a known load)
law-mistake-robust-2 = it writes the robust term −h2²/(4·ε2)·z2 of (38) without the switch robust, so it acts while the robust terms are off
law-mistake-psi-modulus = it takes ψ_d as the flux modulus (ψ_d²) where the paper's z3 = x̂4² + x̂5² − ψ_d takes it as the squared modulus
law-mistake-factor-2 = it drops the factor 2 throughout ψ3: the rate of x̂4² + x̂5² is 2·(x̂4·x̂̇4 + x̂5·x̂̇5)
law-mistake-residual-rates = it leaves out the residuals' chain-rule terms 2·(l41·x̂4 + l51·x̂5)·ẋ̃2 and 2·(l42·x̂4 + l52·x̂5)·ẋ̃3 of ψ4
law-mistake-drifts = it has the model's drifts f̂4, f̂5 where ψ4 has the observer's rates x̂̇4 = f̂4 + si4 and x̂̇5 = f̂5 + si5: the injections are left out
law-mistake-drift-4 = it has the model's drift f̂4 where ψ4 has the observer's rate x̂̇4 = f̂4 + si4: the injection si4 is left out
law-mistake-drift-5 = it has the model's drift f̂5 where ψ4 has the observer's rate x̂̇5 = f̂5 + si5: the injection si5 is left out
law-mistake-factor-si4 = the factor of x̂̇4 leaves out si4: the rate of 2·x̂4·si4 in ψ3 gives 2·si4·x̂̇4
law-mistake-factor-si5 = the factor of x̂̇5 leaves out si5: the rate of 2·x̂5·si5 in ψ3 gives 2·si5·x̂̇5
law-mistake-robust-4 = it writes the robust term −h4²/(4·ε4)·z4 of (53) without the switch robust, so it acts while the robust terms are off

## The names a law may use: what each one means (its name, symbol and unit are shown beside it)

formula-name-x1h = estimated rotor speed ω̂ (posterior x̂1)
formula-name-x2h = estimated stator current î_sa
formula-name-x3h = estimated stator current î_sb
formula-name-x4h = estimated rotor flux φ̂_ra
formula-name-x5h = estimated rotor flux φ̂_rb
formula-name-x2 = measured stator current i_sa
formula-name-x3 = measured stator current i_sb
formula-name-xt2 = residual x̃2 = x2 − x̂2
formula-name-xt3 = residual x̃3 = x3 − x̂3
formula-name-dxt2 = nominal rate of x̃2: −(a7 + l21)·x̃2 − l22·x̃3
formula-name-dxt3 = nominal rate of x̃3: −l31·x̃2 − (a7 + l32)·x̃3
formula-name-dx4h = observer rate of x̂4: −a8·x̂4 − a9·x̂1·x̂5 + a10·x̂2 + si4
formula-name-dx5h = observer rate of x̂5: −a8·x̂5 + a9·x̂1·x̂4 + a10·x̂3 + si5
formula-name-wd = speed reference ω_d
formula-name-dwd = its first derivative
formula-name-ddwd = its second derivative
formula-name-psi-d = flux target for x̂4² + x̂5²
formula-name-si1 = observer injection into x̂1: l11·x̃2 + l12·x̃3
formula-name-si2 = observer injection into x̂2
formula-name-si3 = observer injection into x̂3
formula-name-si4 = observer injection into x̂4
formula-name-si5 = observer injection into x̂5
formula-name-l11 = observer gain L = K/Ts, row 1, column 1
formula-name-l12 = observer gain, row 1, column 2
formula-name-l21 = observer gain, row 2, column 1
formula-name-l22 = observer gain, row 2, column 2
formula-name-l31 = observer gain, row 3, column 1
formula-name-l32 = observer gain, row 3, column 2
formula-name-l41 = observer gain, row 4, column 1
formula-name-l42 = observer gain, row 4, column 2
formula-name-l51 = observer gain, row 5, column 1
formula-name-l52 = observer gain, row 5, column 2
formula-name-a1 = μ = 3·np·M/(2·J·Lr): a1·(x3·x̂4 − x2·x̂5) is the torque over J
formula-name-a2 = T0/J (the estimate â2 when the EKF estimates the load)
formula-name-a3 = Cf/J
formula-name-a5 = α·β, with α = Rr/Lr and β = M/(σ·Lr)
formula-name-a6 = np·β
formula-name-a7 = γ = Rs/σ + α·β·M
formula-name-a8 = α = Rr/Lr
formula-name-a9 = np
formula-name-a10 = α·M
formula-name-b = 1/σ
formula-name-da2 = rate of â2 (its injection) when the EKF estimates the load, else 0
formula-name-k1 = speed-error rate
formula-name-k2 = torque-error rate (k2 = a7 + a8 + k2s1)
formula-name-k3 = flux-error rate
formula-name-k4 = flux-rate-error rate
formula-name-k1s1 = k1 − a3
formula-name-k2s1 = k2 − a7 − a8
formula-name-h2 = bound on |d̃2| of (38)
formula-name-eps2 = ε2 of (38)
formula-name-h4 = bound on |d̃4| of (53)
formula-name-eps4 = ε4 of (53)
formula-name-robust = 1 when the robust terms (38) and (53) are on, else 0
formula-name-z1 = speed error x̂1 − ω_d
formula-name-z3 = flux error x̂4² + x̂5² − ψ_d
formula-name-v1 = step 1's virtual control (yours when you wrote it)
formula-name-z2 = torque error a1·(x3·x̂4 − x2·x̂5) − v1
formula-name-v3 = step 3's virtual control (yours when you wrote it)
formula-name-z4 = flux-rate error 2·a10·(x2·x̂4 + x3·x̂5) − v3

## The functions a law may call: each one written with its arguments, and what it gives (the
## function's name and its arguments are the language's: keep them)

formula-function-sqrt = sqrt(x): square root
formula-function-exp = exp(x): exponential
formula-function-ln = ln(x): natural logarithm
formula-function-sin = sin(x): sine, x in rad
formula-function-cos = cos(x): cosine, x in rad
formula-function-tanh = tanh(x): hyperbolic tangent
formula-function-abs = abs(x): absolute value
formula-function-sign = sign(x): −1, 0 or 1
formula-function-atan2 = atan2(y, x): the angle of (x, y) (rad)
formula-function-min = min(a, b): the smaller
formula-function-max = max(a, b): the larger
formula-function-sat = sat(x, m): x limited to [−m, m]
