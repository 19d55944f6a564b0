# The core's words about a run: what each setting means, what each preset shows, the figures of
# a run and the part of the run each covers, the warnings they must not be read without, where the
# start-up transient ends, and why a run stopped. The CLI says them in English from this file
# (`imlab describe`, `imlab presets`, `imlab metrics`); the page in the reader's language. Keys
# and field names (k1, law.v1, ekf.q), the values a field takes (euler, rk4, box), symbols
# (ω_d, φa², Rs, |i_s|), units, formulas and the paper's equation and figure numbers ((38),
# Fig 2) are the link's and the paper's own: keep them as they are.

## A time

# A time in milliseconds or in seconds, with up to 4 significant digits.
time-ms = { $ms } ms
time-s = { $s } s

## What each setting means (its key, unit and range are the codec's own)

# (0/1) marks a switch: 0 off, 1 on.

field-design = design: paper (the values set) or derived from the motor's data
field-ref = speed reference kind
field-ref-value = constant speed
field-sine-amp = sine amplitude
field-sine-freq = sine frequency
field-sine-offset = constant added to the sine
field-step-size = step size
field-step-time = step time
field-step-wn = step filter natural frequency ωn
field-ramp-start = ramp start time
field-ramp-level = ramp plateau level
field-ramp-slope = ramp slope magnitude
field-ramp-hold = ramp plateau duration
field-rev-start = reversal run-up start time
field-rev-level = speed reversed, +level to −level
field-rev-slope = reversal slope magnitude
field-rev-hold = time at +level before reversing
field-ref-table = reference as a table of points t:ω_d, straight between them
field-psi_d = flux target for φa² + φb²
field-fw = field weakening above base speed (0/1)
field-fw-base = base speed of the field weakening
field-k1 = speed-error rate k1
field-k2 = torque-error rate k2 = a7 + a8 + k2s1
field-k3 = flux-error rate k3
field-k4 = flux-derivative-error rate k4
field-robust = apply robust terms (38) and (53) (0/1)
field-eps2 = ε2 of (38): the bound on z2·(v2s2 + d̃2)
field-h2 = h2 of (38): bound on |d̃2|
field-eps4 = ε4 of (53): the bound on z4·(v4s2 + d̃4)
field-h4 = h4 of (53): bound on |d̃4|
field-law-v1 = your step 1: the virtual control v1 (empty: the paper's (26))
field-law-v2 = your step 2: v2 (empty: the paper's (34))
field-law-v3 = your step 3: the virtual control v3 (empty: the paper's (45))
field-law-v4 = your step 4: v4 (empty: the paper's (49))
# backstepping and ifoc are the field's values: keep them as they are.
field-controller = backstepping (paper) or ifoc (classical sensorless FOC baseline)
field-ifoc-bw_i = IFOC current-loop bandwidth
field-ifoc-bw_w = IFOC speed-loop bandwidth
field-ifoc-bw_mras = IFOC MRAS speed-estimator bandwidth
field-ifoc-i_max = IFOC q-current limit
field-ifoc-ff = IFOC torque feedforward J·ω̇_d + T0 + Cf·ω_d (0/1)
# euler and rk4 are the field's values: keep them as they are.
field-ekf = EKF predictor: euler (paper) or rk4
field-ekf-q = process noise Q = q·Ts·I, one number for every state: A²/s for the currents, (rad/s)²/s for ω, Wb²/s for the fluxes
field-ekf-q_speed = process noise added to the speed state alone, Q_ωω = (q + q_speed)·Ts
field-ekf-r_std = assumed current noise, R = r_std²·I
field-ekf-load = estimate the load a2 = T_L0/J as an EKF state (0/1)
field-ekf-q_load = random-walk intensity of the load torque
field-ekf-load_std = initial standard deviation of the load estimate
field-ekf-rr = estimate the rotor resistance R_r as an EKF state (0/1)
field-ekf-q_rr = random-walk intensity of the rotor resistance
field-ekf-rr_std = initial standard deviation of the R_r estimate
field-init_err = initial relative estimation error
field-start = start state: paper (2 A, 2 A, 0.5 Wb, 0.5 Wb) or magnetized at the flux target
field-perfect = perfect observer: controller gets the true state (0/1)
field-noise = current-measurement noise std
field-seed = noise seed
# The simulated motor's parameters, the plant's; the model's, what the controller and the observer
# assume, read the same.
field-motor = motor of the plant and the model together, with its rated current
field-plant-rs = stator resistance Rs
field-plant-rr = rotor resistance Rr
field-plant-m = mutual inductance M
field-plant-ls = stator inductance Ls
field-plant-lr = rotor inductance Lr
field-plant-j = rotor inertia J
field-plant-np = pole pairs np
field-plant-t0 = constant load torque T0
field-plant-cf = viscous friction Cf
field-model-rs = { field-plant-rs }
field-model-rr = { field-plant-rr }
field-model-m = { field-plant-m }
field-model-ls = { field-plant-ls }
field-model-lr = { field-plant-lr }
field-model-j = { field-plant-j }
field-model-np = { field-plant-np }
field-model-t0 = { field-plant-t0 }
field-model-cf = { field-plant-cf }
field-load-time = time of the unknown load step
field-load-torque = size of the unknown load step
field-load-table = unknown load torque as a table of points t:torque, straight between them (instead of the step)
field-vmax = voltage limit per component
field-duration = simulated time
field-ts = sampling period Ts
field-substeps = plant RK4 substeps per sample
field-i_rated = rated current: amplitude |i_s| of the rated phase current
field-rated-v = rated voltage, line to line rms
field-rated-f = rated frequency
field-delay = computation delay: u_k applied one sample later (0/1)
field-delay-comp = delay compensation: control from the one-step prediction x̂(k+1|k) (0/1)
# box, circle and hex are the field's values: keep them as they are.
field-vlimit = voltage limit: box (±vmax per component, the paper), circle (|u| ≤ vdc/√3) or hex (two-level inverter)
field-vdc = DC-link voltage of the circle and hex limits and of PWM
field-pwm = two-level inverter, symmetric PWM at the sampling rate (0/1; vlimit circle or hex)

## What each preset shows (preset-NAME: the preset NAME)

# A preset's name in a description (sine200, load-step, rr-mismatch) is the link's: keep it as it is.

preset-sine200 = Paper Fig 2: track 0.5 sin(2π·200 t) rad/s with the EKF; the current peaks above the motor's rated current
preset-step = Paper Fig 3: 0 → 0.5 rad/s step at 50 ms through a 200 Hz critically damped filter
preset-ramp = Paper Fig 4: trapezoid to 100 rad/s at ±400 rad/s², hold, and back
preset-sine200-1rad = 1 rad/s at 200 Hz: saturates the 400 V limit, and its tracking error is more than three times sine200's
preset-sine200-rk4 = Fig 2 with an RK4 EKF predictor instead of the paper's Euler
preset-rr-mismatch = Hold 50 rad/s with the motor's rotor resistance 10 % above the model's: the true speed recovers from the start-up over seconds and settles above the reference (run it for 6 s to see it end)
preset-load-step = Hold 50 rad/s; an unknown 2 N m load step at 0.15 s that the 5-state EKF cannot see
preset-decay = Perfect observer, no noise, ω_d ≡ 0: the errors decay at the designed 1200/s, then stop at a floor that shrinks with the sampling period
preset-ifoc-step = Classical baseline: sensorless IFOC with an MRAS, step to 40 rad/s (MRAS is blind near zero speed)
preset-load-step-est = load-step with the load a2 as an EKF state (RK4 predictor): the speed holds through the unknown step with an exact model, not with the motor's R_r 3 % below the model's
preset-rr-mismatch-est = rr-mismatch with R_r as an EKF state (RK4 predictor): no slow transient, and R̂_r stays near the motor's value
preset-sine200-drive = Does 200 Hz survive a real drive? sine200 with a one-sample computation delay, the 540 V inverter hexagon and PWM
preset-high-gain = Gains 3000/s (2.5× the paper): the Euler EKF's prediction errors through the gains saturate the 400 V limit

## The figures of a run (`imlab metrics` names them by the part after figure-)

figure-transient_end = start-up transient ends
figure-tracking_rms = RMS of ω − ω_d
figure-tracking_peak = peak |ω − ω_d|
figure-settling_time = 2 % settling time of ω after the step
figure-saturated_share = share of samples at the voltage limit
figure-mean_nis = mean NIS
figure-mean_nis_low = mean NIS, low end of a consistent filter's 95 % band
figure-mean_nis_high = mean NIS, high end of a consistent filter's 95 % band
figure-current_peak = peak stator current |i_s|
figure-current_rms = RMS stator current |i_s|
figure-current_rated = rated current |i_s| (i_rated)
figure-ripple_peak = peak PWM current ripple
figure-ripple_rms = RMS over the periods of the peak PWM current ripple
figure-flux_error_final = final flux error |φ_r| − √ψ_d
figure-speed_error_final = final speed error ω − ω_d
figure-speed_estimate_error_final = final speed-estimate error ω − ω̂
figure-law_residual = largest residual of your laws' designed dynamics, over the run and at the verdict's drawn states, relative to the paper's law
# Not among the run's figures: a challenge may name it.
figure-load_recovery_time = load recovery time after the load step

## The part of the run a figure covers

# $time is a time (time-ms or time-s): where the start-up transient ends.
window-after-transient = t ≥ { $time }
window-start-up = start-up, t < { $time }
# $time is the time of the reference's step.
window-from-step = from the step at { $time }
window-rating = the motor's rating
# $time is the time of the run's last sample.
window-last-sample = last sample, t = { $time }
window-law-residual = the whole run and the verdict's drawn states

## A figure the run had not reached by its end, said in place of its value

# $time is the time of the run's last sample.
unreached-not-settled = not settled by the end of the run (t = { $time })

## What a run's figures must not be read without

# $speed is ω − ω_d at the run's end, $estimate ω̂ − ω, $flux the flux modulus and $target its
# target √ψ_d.
warning-runaway = The run ran away: at its end the true speed is { $speed } rad/s from the reference, the speed estimate { $estimate } rad/s from the true speed, and the flux { $flux } Wb against its target of { $target } Wb. The controller regulates the EKF's estimates; Theorem 4.6 bounds the closed loop only while the estimation errors stay bounded, and when they do not (a start-up error held only by the voltage limit, a wrong model at low speed) nothing bounds the motor.
# $low and $high are the ends of the band.
warning-inconsistent-above = The EKF is inconsistent on this run: its mean NIS is { $nis }, far above the 95 % band { $low }–{ $high } of a filter whose model fits. Its estimates, and the speed the controller acts on, may be far from the truth however narrow their bands look.
warning-inconsistent-below = The EKF is inconsistent on this run: its mean NIS is { $nis }, far below the 95 % band { $low }–{ $high } of a filter whose model fits. It assumes more noise than there is, so it follows the measurements more slowly than it could.
# The speed off its reference to the end of the run: $since the time it has been off since (a
# time-ms or time-s), $error ω − ω_d at the end and $reference ω_d there (rad/s); off means
# beyond $share % of |ω_d| plus $margin rad/s.
warning-not-following = The speed does not follow its reference: from t = { $since } to the end of the run, ω − ω_d stays beyond ±({ $share } % of |ω_d| + { $margin } rad/s), and it ends at { $error } rad/s with ω_d = { $reference } rad/s.
# As warning-not-following, off over the whole window of the figures, which starts at $since.
warning-not-following-window = The speed does not follow its reference: over the whole window of the figures, from t = { $since } to the end of the run, ω − ω_d stays beyond ±({ $share } % of |ω_d| + { $margin } rad/s), and it ends at { $error } rad/s with ω_d = { $reference } rad/s.
# $figure is the figure's name (law_residual); $cause says why it is not a number.
warning-not-finite = { $figure } is not a finite number: { $cause }.

## Where the start-up transient ends, and why there

transient-nothing-recorded = nothing recorded yet
# In place of a time: the criterion was never met in the first half of the run.
transient-never = never in the first half (not used)
# $k is the smallest of the gains k1..k4 (1/s); $time the controller's start-up.
transient-backstepping = 5 time constants of the slowest designed error rate (1/{ $k } s) = { $time }
# $bw is the IFOC current-loop bandwidth ifoc.bw_i (Hz); $time the controller's start-up.
transient-ifoc = 5 time constants of the IFOC current loops (1/(2π·{ $bw } Hz)) = { $time }
# $controller is transient-backstepping or transient-ifoc; $observer, $estimates, $flux and $speed
# are times, or transient-never; $end is event when the transient was cut at the scenario's first
# event (the step or the load step), half when it was clamped to half the run, else none; $at is
# the time of that event or of half the run.
transient-reason = { $controller }, counted from the observer's start-up. EKF innovation covariance settled (2σ band within 10 % of its final value): { $observer }; EKF estimates converged (2 ms mean NIS within twice its level in the second half, for 5 ms): { $estimates }; flux estimate within 1.5 times its later RMS error (for 5 ms): { $flux }; speed estimate within twice its later RMS error (5 ms windows, for 5 ms): { $speed }{ $end ->
        [event] ; cut at the scenario's first event, at { $at }
        [half] ; clamped to half the recorded run ({ $at })
       *[none] {""}
    }

## Why a run stopped

# $t is the sample's time (s); $signal the state that left its bounds (omega, i_sa, phi_a…);
# $value its value, in scientific notation (1.2e5, NaN).
sim-diverged = diverged at t = { $t } s: { $signal } = { $value } left its bounds
# $column is a column of the run's CSV; $value is inf, -inf or NaN.
sim-not-finite = stopped at t = { $t } s: column '{ $column }' would record { $value }, not a finite number
# $error is a control-* message.
sim-control = controller failed at t = { $t } s: { $error }
# $formula is the student's law as typed; $value is inf, -inf or NaN; $reading is
# sim-law-reads-nothing or sim-law-reads.
sim-law = your law.v{ $step } = { $formula } gave { $value } at t = { $t } s, { $reading }
sim-law-reads-nothing = reading no signal
# $signals lists the names the law reads with their values there (x1h = 52.3, z1 = 0.01).
sim-law-reads = from { $signals }
# $flux and $min in scientific notation (Wb²).
control-singular = decoupling matrix (55) is singular: estimated flux x̂4² + x̂5² = { $flux } Wb² is below { $min } Wb²
control-law = the law of step { $step } gave { $value }, not a finite number
# The most runs that can be pinned at once ($max).
pin-room-full = at most { $max } runs can be pinned; unpin one first
# A pin's legend when its scenario is the current run's.
pin-legend-same = same scenario
# $scenario: the pinned run's link; $pinned and $current: the two sampling periods (s).
overlay-ts-differs = the pinned run { $scenario } samples at Ts = { $pinned } s, the current one at { $current } s: overlays need the same Ts
