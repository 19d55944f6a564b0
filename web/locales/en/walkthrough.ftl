# The design walkthrough (web/teaching/walkthrough*.js): each section's title, prose, notes, figure,
# the titles of its plots and the labels of their signals, the step's own law, the stability
# report and the comparison of the EKF's predictors. The equations are not here: they stay as the
# paper writes them. A number about a run is a variable named by its row of the measurements table
# (web/teaching/measurements/walkthrough.csv): { $wt-z3-min } is the row wt.z3.min, and
# { $wt-ekf-euler-nis--draws } the number of noise draws of the row wt.ekf.euler.nis. A translation
# keeps every variable of the English message and states no number the English does not.
# A brace of the text (as in u_{"{"}k−1{"}"}) is written {"{"} and {"}"}.

## Section model (walkthrough-text.js): 1. The motor model (2)

walkthrough-model-title = 1. The motor model (2)
walkthrough-model-prose-1 = The state is the rotor speed ω = x1, the stator currents i_sa, i_sb = x2, x3 and the rotor fluxes φ_ra, φ_rb = x4, x5 in the stationary a–b frame. Only the currents are measured; the voltages u1, u2 are the inputs.
walkthrough-model-prose-2 = The torque over the inertia is a1(x3·x4 − x2·x5), in rad/s²: current crossed with flux (a1 = 3n_pM/(2JL_r) already contains 1/J, so multiply by J for N m). The load a2 + a3·x1 is the constant T0 and the friction Cf·ω over J. The lumped parameters below are computed by the core from the motor parameters in use; the plant (the simulated motor) and the model (what the EKF and controller assume) can differ.
walkthrough-model-note = σ here is in henry: the paper’s σ = L_s − M²/L_r is the total leakage inductance seen from the stator (the transient inductance), not the stator’s own leakage L_s − M; many texts write the dimensionless σ = 1 − M²/(L_sL_r) instead.
walkthrough-model-plot-title = Speed and flux

## Section ekf (walkthrough-text.js): 2. The extended Kalman filter (10)–(20)

walkthrough-ekf-title = 2. The extended Kalman filter (10)–(20)
walkthrough-ekf-prose-1 = The EKF estimates all five states from the measured currents and the applied voltages. It predicts with the model discretised by forward Euler (10), linearised by the Jacobian (11), and corrects with the innovation: the measured minus the predicted currents.
walkthrough-ekf-prose-2 = Q (process noise: q·Ts on every state, plus q_speed·Ts on the speed alone) says how much the model is trusted; R (measurement noise, r_std²·I) how much the sensors are. One q for states of mixed units is the paper’s choice; q_speed lets the speed estimate move without loosening the rest. The gain K_k enters the controller as the observer gain L = K_k/Ts of the general form (4): the estimation errors x̃ are what the controller must tolerate.
walkthrough-ekf-prose-3 = A consistent filter has innovations inside their ±2σ band about 95 % of the time and a normalised innovation squared (NIS) averaging 2. Ranges and bounds in this walkthrough are over { $wt-ekf-euler-nis--draws } noise draws (seeds 1 to { $wt-ekf-euler-nis--draws }). The Euler predictor cannot follow 200 Hz currents: on sine200 its NIS averages at least { $wt-ekf-euler-nis } on every draw, the RK4 predictor’s at most { $wt-ekf-rk4-nis }; compare them below.
walkthrough-ekf-prose-4 = Section 3.1 names a remedy it does not build: treat slowly varying quantities as extra states. The knob ekf.load adds a2 = T_L0/J as a random walk (the controller then uses â2 and its rate, the injection l_a·(x̃2, x̃3)); ekf.rr adds the rotor resistance (the controller’s a5, a7, a8, a10 follow R̂_r). The last two plots show both estimates with their ±2σ bands from P against the truth. An extra state absorbs whatever the model lacks, right or wrong: a rotor-resistance state under an unknown load takes the load for a resistance (see the lessons).
walkthrough-ekf-note = Printed (13) predicts with u_{"{"}k|k−1{"}"}; the voltage that acted over the last sample is u_{"{"}k−1{"}"}, which (10) uses and so does the filter here. The Joseph form writes the covariance update (19) as a sum of two symmetric terms, each positive semidefinite for any gain K: rounding is much less able to make P lose either property than in the short form (I − K_kC)P_{"{"}k|k−1{"}"}, though nothing guarantees it.
walkthrough-ekf-plot-title = Innovation ỹ_a with its ±2σ band from S_k
walkthrough-ekf-plot4-title = Normalised innovation squared with its 95 % band (χ², 2 dof)
walkthrough-ekf-plot2-title = Speed estimate and its variance
walkthrough-ekf-plot3-title = Flux modulus: true and estimated
walkthrough-ekf-plot5-title = Load torque: estimate â2·J with its ±2σ band, and the truth
walkthrough-ekf-plot6-title = Rotor resistance: estimate with its ±2σ band, and the motor’s

## Section bridge (walkthrough-text.js): 3. From the observer to the controller: (4) and (5)

walkthrough-bridge-title = 3. From the observer to the controller: (4) and (5)
walkthrough-bridge-prose-1 = The controller never sees the motor’s state, only the observer’s estimate x̂ and the measured currents x2, x3. Write the estimation error x̃ = x − x̂. Two of its components are measured: the current residuals x̃2 = x2 − x̂2 and x̃3 = x3 − x̂3. Three are not: the speed error x̃1 and the flux errors x̃4, x̃5.
walkthrough-bridge-prose-2 = The paper designs the controller against an observer of the general form (4): the model (2) copied with the estimates, plus an injection si_i = l_i1·x̃2 + l_i2·x̃3 (5), a correction that pulls each estimate by the measured residuals. Read as a forward-Euler step, the EKF’s update has this form with L = K_k/Ts and the prior residual y_k − Cx̂_{"{"}k|k−1{"}"} (15), in rows 2 to 5. Row 1 only nearly: the EKF’s torque term reads the estimated currents x̂2, x̂3 where (4) reads the measured x2, x3. The controller here uses the posterior residual y_k − Cx̂_{"{"}k|k{"}"} = (I − CK_k)(y_k − Cx̂_{"{"}k|k−1{"}"}), which fits x̃ = x − x̂ for the posterior x̂_{"{"}k|k{"}"} it uses; the two agree only while CK_k is small.
walkthrough-bridge-prose-3 = Subtracting (4) from (2) gives the error dynamics below. The controller differentiates the measured residuals (they are in v1 and in ψ3), and their derivatives hold the unmeasured x̃1, x̃4, x̃5. Each such derivative is split in two: the nominal residual dynamics, what ẋ̃2 and ẋ̃3 would be with x̃1 = x̃4 = x̃5 = 0, which the controller computes, and the rest, which it cannot. The design also takes L as constant: L̇ is neglected everywhere below.
walkthrough-bridge-prose-4 = That is the integrated design the paper is named for: the observer’s error dynamics are inside the controller’s design, and the unknown terms appear only where a measured current or a residual is differentiated, in step 2 (ż2 holds ẋ2, ẋ3 and v̇1) and in step 4 (ż4 holds the rates of the injections si4, si5). Steps 1 and 3 have none. There they are collected as d̃2 and d̃4 and treated as bounded disturbances. With an exact model that is all of them; a model that differs from the motor adds terms of its own to ż2 and ż4, which the paper’s d̃2 and d̃4 do not have.
walkthrough-bridge-prose-5 = What the integration replaces is the time-scale separation the paper’s abstract names: an observer made so much faster than the controller that the controller may treat its estimate as the state. The laws below still put x̂ where a state-feedback law would put x, the form of certainty equivalence; what the design adds is that the estimation errors enter its Lyapunov argument, as d̃2 and d̃4 bounded under Assumption 4.2, instead of being assumed away.
walkthrough-bridge-figure = The controller and the observer, as in the paper’s Fig. 1: the controller sees the motor only through the EKF’s estimate, gain and residuals, and the measured currents.
    .alt = Block diagram: the reference and the EKF’s estimate, gain and residuals go into the backstepping controller; its voltage passes the voltage limit and drives the motor; the measured currents and the applied voltage go back into the EKF.
walkthrough-bridge-note = The paper writes si_i(x̃2, x̃3) for the injection; here si_i is its value l_i1·x̃2 + l_i2·x̃3. The letter ψ names both the flux target ψ_d and the known terms ψ2, ψ3, ψ4 of the steps below: they are unrelated.

## Section step1 (walkthrough-text.js, walkthrough-laws.js): 4. Step 1: the speed loop

walkthrough-step1-title = 4. Step 1: the speed loop
walkthrough-step1-prose-1 = Step 1 regulates the estimated speed: z1 = x̂1 − ω_d. Its derivative, from the first line of (4), is the open loop (23). Split the friction term about the reference, −a3·x̂1 = −a3·z1 − a3·ω_d: the motor’s own damping −a3·z1 stays, and −a3·ω_d is a known term.
walkthrough-step1-prose-2 = A virtual control is a signal that a step treats as its input though the motor has no such input. Step 1’s is the torque term a1(x3·x̂4 − x2·x̂5), built from measured currents and estimated fluxes: ask it to equal v1 (a torque over the inertia, rad/s²) and name the shortfall z2 (24). Then (25) holds.
walkthrough-step1-prose-3 = Choose v1 = v1a + v1s (26). The feedforward v1a (27) cancels every known term; si1 is known, since it uses the measured residuals only. The feedback v1s = −k1s1·z1 (28) leaves (29), ż1 = −k1·z1 + z2 with k1 = a3 + k1s1: k1s1 is the part of the rate k1 that the controller adds to the motor’s own damping a3, so v1a holds a3·ω_d and not a3·x̂1. Steps 1 and 2 keep the motor’s own damping; steps 3 and 4 cancel all they know.
walkthrough-step1-prose-4 = Step 1’s Lyapunov function is V1 = ½z1². Along (29), V̇1 = z1ż1 = −k1z1² + z1z2: negative but for the cross term z1z2, which step 2 cancels.
walkthrough-step1-prose-5 = Step 2 needs v̇1. Differentiate (30) with L constant (L̇ neglected): the injection’s rate is l11·ẋ̃2 + l12·ẋ̃3, and ẋ̃2, ẋ̃3 hold the unmeasured x̃1, x̃4, x̃5 (section 3). The known part of v̇1 puts the nominal residual dynamics in their place; the rest, the “…” below, goes into d̃2.
walkthrough-step1-note = Printed (31) has a3·ω_d and â2 where a3·ω̇_d and dâ2/dt belong (corrected above). The “…” are the x̃1, x̃4, x̃5 terms: −(l11·a5 − l12·a6·x̂1)·x̃4 − (l12·a5 + l11·a6·x̂1)·x̃5 − (l11·a6·x5 − l12·a6·x4)·x̃1.
walkthrough-step1-plot-title = Step 1: z1, v1 = v1a + v1s and the torque term
walkthrough-step1-plot3-title = Step 1: ż1 as the run made it (its change over each sample, over Ts) against the designed −k1·z1 + z2
walkthrough-law-1-intro = Derive v1 yourself and write it below as a formula of this section’s names (x1h for x̂1, wd and dwd for ω_d and ω̇_d, si1, a2, a3, k1s1, z1; the full list is below), with + − * / ^, parentheses and functions. It runs at 20 kHz in place of the paper’s (26) as soon as you press Enter or pause; an empty field gives the paper’s law back. After the run, the verdict checks your law against the designed dynamics ż1 = −k1·z1 + z2 at drawn states and parameter values, and the plot below shows its residual over the run: zero for a law that gives them.
walkthrough-law-1-plot-title = Step 1: your law’s residual, ż1 against the designed ż1 = −k1·z1 + z2 (your v1 less the paper’s)

## Section step2 (walkthrough-text.js, walkthrough-laws.js): 5. Step 2: the torque loop

walkthrough-step2-title = 5. Step 2: the torque loop
walkthrough-step2-prose-1 = Step 2 makes the torque term follow v1 by driving z2 to zero, and here the voltages appear for the first time. Differentiate (24): ẋ2 and ẋ3 bring bu1 and bu2, so v2 = b·a1(x̂4·u2 − x̂5·u1) is the input; x̂̇4, x̂̇5 are those of (4); and −v̇1 is (31). Group what the controller knows into ψ2, and write the torque term as z2 + v1: (32) follows.
walkthrough-step2-prose-2 = ψ2 collects everything known: the flux and current dynamics, the injections si4, si5 and the known part of v̇1. The unmeasured errors x̃1, x̃4, x̃5 enter only through d̃2 (33) (with an exact model; a model that differs from the motor adds terms of its own to ż2): linear in them, with coefficients built from x̂, x and L, so bounded while x̂, x, L and x̃ are. The paper keeps x̂ bounded with a projection (7)–(9); that bounds x̂, not x̃, and while the projection acts x̂̇ is no longer (4), nor ψ2–ψ4 exact. The EKF here has no projection: nothing but the run itself bounds x̂.
walkthrough-step2-prose-3 = Choose v2 = v2a + v2s (34): v2a = −ψ2 − z1 cancels the known terms and the cross term z1z2 of V̇1; v2s = −k2s1·z2 + v2s2 (36) adds the feedback, with k2 = a7 + a8 + k2s1 since the motor supplies the damping a7 + a8 itself. For the paper’s motor a7 + a8 = 232.7 /s, so k2s1 = 967.3 /s when k2 = 1200 /s.
walkthrough-step2-prose-4 = The robust term v2s2 = −h2²z2/(4ε2) (38) dominates d̃2 if h2 bounds |d̃2|. With V_s2 = ½(z1² + z2²) (39), V̇_s2 = −k1z1² − k2z2² + z2(v2s2 + d̃2) ≤ −k1z1² − k2z2² + ε2 (40). No finite h2 does this for a d̃2 that grows without bound: once |d̃2| passes h2, z2(v2s2 + d̃2) can exceed ε2.
walkthrough-step2-prose-5 = Which terms go to d̃2 is a choice: (33) writes the true speed as x1 = x̂1 + x̃1 and keeps the x̂1 part in ψ2; another split would move terms between ψ2 and d̃2 and leave ż2 the same. Assumption 4.2 (22) is what the paper leans on here: it takes x̃ to lie in a known box [x̃_min, x̃_max], says that d̃2 is then bounded, and sets h2 to that bound (38), as step 4 sets h4 (53). It gives no value for the box or the bounds. Here h2 and h4 are settings; the d̃2 plot below and step 4’s d̃4 plot measure the terms on the run shown, one way to size them for that run. ε2 then trades the floor ε/λ of (59) against the rate h2²/(4ε2) that v2s2 adds to z2’s, and a loop sampled every Ts holds a rate only well below about 2/Ts; the lesson “The robust terms and the bound (59)” works one choice through.
walkthrough-step2-prose-6 = Differentiating z2 also gives −(a7 + a8)·z2, the motor’s own damping; (32) as printed drops it, and the k2 = a7 + a8 + k2s1 of (36) counts it.
walkthrough-step2-note = Printed (35) is v2a = −ψ2 − d̃2 − z1: d̃2 is unknown, so no controller can subtract it; the controller here uses −ψ2 − z1 and leaves d̃2 to the robust term.
walkthrough-step2-shows-1 = The plot below evaluates d̃2 from the simulated truth: the motor’s actual ż2 less the terms the controller knows, with the true currents in place of the measured ones. It is evaluated for the five-state EKF without the delay compensation; for an observer with extra states (ekf.load, ekf.rr) or with delay.comp the plot stays empty. h2 must be at least the peak of |d̃2| for (38) to dominate it: read it on step with an exact model, then with a model error (plant.j, plant.rr). With the motor’s R_r 10 % above the model’s (plant.rr = 5.445) the loop runs away or fails on { $wt-rrhigh-runaway } of { $wt-rrhigh-runaway--draws } draws: the flux runs off on { $wt-rrhigh-off } and the controller fails before the end on { $wt-rrhigh-fail }. The flux ends the preset’s 0.1 s at { $wt-rrhigh-flux-min } to { $wt-rrhigh-flux-max } Wb and is { $wt-rrhigh1s-flux-min } to { $wt-rrhigh1s-flux-max } Wb after 1 s, and the coefficients of d̃2 in (33) grow with x.
walkthrough-step2-plot-title = Step 2: z2 and v2 = v2a + v2s
walkthrough-step2-plot2-title = Step 2: d̃2 evaluated from the simulated truth, against ±h2
walkthrough-step2-plot3-title = Step 2: ż2 as the run made it (its change over each sample, over Ts) against the designed −k2·z2 − z1 (with its robust term when robust=1)
walkthrough-law-2-intro = Derive v2 yourself and write it below as a formula of this section’s names (v1 and z2 (from step 1), x2 and x3, x4h and x5h, si4 and si5, dxt2 and dxt3, l11 and l12, ddwd, a1 to a10, k1, k1s1, k2s1; the full list is below), with + − * / ^, parentheses and functions. It runs at 20 kHz in place of the paper’s (34) as soon as you press Enter or pause; an empty field gives the paper’s law back. With your own v1 under step 1, your v2 is judged on it: it must differentiate your v1, with the ż1 your v1 gives. After the run, the verdict checks your law against the designed dynamics ż2 = −k2·z2 − z1 at drawn states and parameter values, and the plot below shows its residual over the run: zero for a law that gives them.
walkthrough-law-2-plot-title = Step 2: your law’s residual, ż2 against the designed ż2 = −k2·z2 − z1 (your v2 less the v2 that gives it: the paper’s, or after your own v1 the one that differentiates yours)

## Section step3 (walkthrough-text.js, walkthrough-laws.js): 6. Step 3: the flux outer loop

walkthrough-step3-title = 6. Step 3: the flux outer loop
walkthrough-step3-prose-1 = Step 3 regulates the estimated flux modulus squared: z3 = x̂4² + x̂5² − ψ_d (42). Its derivative needs only (4): ż3 = 2x̂4·x̂̇4 + 2x̂5·x̂̇5 − ψ̇_d, in which the a9 terms cancel, written in the estimates alone below. Writing x̂2 = x2 − x̃2 and x̂3 = x3 − x̃3 separates the virtual control 2a10(x2·x̂4 + x3·x̂5), the part of ż3 the stator currents drive, from ψ3 (43).
walkthrough-step3-prose-2 = ψ3 depends only on estimates and measured residuals, so Step 3 has no unknown term at all: with v3 = −ψ3 − k3·z3 (45), ż3 = −k3·z3 + z4 (46) holds exactly in continuous time, for the observer’s own flux estimate. Its Lyapunov function is V3 = ½z3², with V̇3 = −k3z3² + z3z4; step 4 cancels the cross term.
walkthrough-step3-prose-3 = Since v3 = −ψ3 − k3·z3, the next error z4 (44) is z4 = ż3 + k3·z3: the rate at which z3 fails to decay at k3.
walkthrough-step3-prose-4 = The paper writes the feedback as v3s = −k3s1·z3 and sets k3 = k3s1 (46): v3a cancels all of ψ3, the flux’s own decay −2a8·(x̂4² + x̂5²) included, so the whole rate k3 is the controller’s, where in step 1 the motor’s damping a3 is part of k1.
walkthrough-step3-note = The problem statement asks x4² + x5² to track ψ_d², but (42) subtracts ψ_d: ψ_d here is the target of the squared modulus, in Wb². The scenario’s psi_d is that target: psi_d = 0.5 Wb² asks for a flux modulus |φ| = 0.707 Wb. The paper’s simulations state “ϕ_d = 0.5” as the desired flux modulus, which read literally is 0.5 Wb (0.25 Wb²); the presets take it as the squared modulus, as (42) uses it, the square of the paper’s initial flux [0.5, 0.5].
walkthrough-step3-shows-1 = The z3 plot shows the error of the observer’s own flux estimate against the target, not the motor’s. On step with an exact model, from 15 ms on, its RMS is { $wt-z3-min } to { $wt-z3-max } mWb² with the EKF and { $wt-z3-quiet } mWb² without measurement noise (noise=0): the noise enters z3 through the innovations. With the perfect observer (perfect=1), whose estimate is the motor’s flux, it stays below { $wt-z3-perfect-max } mWb².
walkthrough-step3-plot-title = Step 3: z3 and v3 = v3a + v3s
walkthrough-step3-plot3-title = Step 3: ż3 as the run made it (its change over each sample, over Ts) against the designed −k3·z3 + z4
walkthrough-law-3-intro = Derive v3 yourself and write it below as a formula of this section’s names (x4h and x5h, xt2 and xt3, si4 and si5, a8, a10, k3, z3; the full list is below), with + − * / ^, parentheses and functions. It runs at 20 kHz in place of the paper’s (45) as soon as you press Enter or pause; an empty field gives the paper’s law back. After the run, the verdict checks your law against the designed dynamics ż3 = −k3·z3 + z4 at drawn states and parameter values, and the plot below shows its residual over the run: zero for a law that gives them.
walkthrough-law-3-plot-title = Step 3: your law’s residual, ż3 against the designed ż3 = −k3·z3 + z4 (your v3 less the paper’s)

## Section step4 (walkthrough-text.js, walkthrough-laws.js): 7. Step 4: the flux inner loop and the voltages

walkthrough-step4-title = 7. Step 4: the flux inner loop and the voltages
walkthrough-step4-prose-1 = Step 4 drives z4 to zero; its input v4 = 2a10·b(x̂4·u1 + x̂5·u2) is the second combination of the voltages. Since z4 = ż3 + k3·z3, ż4 = z̈3 + k3·ż3 = z̈3 + k3(−k3z3 + z4). Differentiate ż3 once more in its form in the estimates alone (the first line of step 3), not in the form (43), whose measured currents would bring unknown terms that cancel: the x̂̇4, x̂̇5 terms gather as below, x̂̇2 and x̂̇3 bring the voltages (v4) and the current dynamics, and the injections’ rates l41·ẋ̃2 + l42·ẋ̃3 and l51·ẋ̃2 + l52·ẋ̃3 bring the residuals’ derivatives.
walkthrough-step4-prose-2 = In the derivative of 2a10·(x2·x̂4 + x3·x̂5) the a6 terms of ẋ2 and ẋ3 (2) cancel in their known part, a6·x̂1·(x̂4·x̂5 − x̂5·x̂4) = 0, which is why ψ4 has no a6; the rest, which holds x̃1, x̃4, x̃5, goes to d̃4. With V_s4 = ½z3² + ½z4² (56), V̇_s4 = −k3z3² − k4z4² + z4(v4s2 + d̃4) ≤ −λ4·V_s4 + ε4 with λ4 = 2·min(k3, k4), which integrates to (57), as section 8 does for V.
walkthrough-step4-prose-3 = ψ4 takes the nominal residual dynamics for ẋ̃2 and ẋ̃3 (section 3), with L̇ neglected: the printed (47) holds with L̇ = 0. What the nominal dynamics leave out, the x̃1, x̃4, x̃5 terms of ẋ̃2 and ẋ̃3 weighted by 2(l41·x̂4 + l51·x̂5) and 2(l42·x̂4 + l52·x̂5), is d̃4.
walkthrough-step4-prose-4 = Choose v4 = −ψ4 − z3 − k4·z4 + v4s2 (49)–(51): the −z3 cancels the cross term z3z4 of V̇3, and (52) follows. v2 and v4 together fix both voltages through the decoupling matrix (54), invertible while the estimated flux is not zero (55). The voltage limit then acts: the paper gives only a 400 V limit; the box (vlimit=box) clips each component to ±400 V, while the circle and the inverter’s hexagon (vlimit) scale the whole vector down, keeping its direction. While it acts, the designed error dynamics no longer hold.
walkthrough-step4-note = Printed (48) has a21, a22 where a41, a42 belong (corrected above). ψ4 above is the printed (47) regrouped: the paper writes 2a10(l21·x̃2·x̂4 + …) for 2a10(x̂4·si2 + x̂5·si3), and splits each x̂̇4, x̂̇5 product in two. Its d̃4 is the same as the printed one, term by term.
walkthrough-step4-shows-1 = |d̃4|, evaluated from the simulated truth as d̃2 is, is plotted below against ±h4; h4 must be at least its peak for (53) to dominate it.
walkthrough-step4-shows-2 = In its first 5 ms the start-up transient commands voltages far beyond the limit: the commanded u_sa peaks at { $wt-cmd-step-min } to { $wt-cmd-step-max } V on step and { $wt-cmd-rr-min } to { $wt-cmd-rr-max } V on rr-mismatch, and on rr-mismatch the limit clips the command until { $wt-clip-rr-min } to { $wt-clip-rr-max } ms. The plots fit their y-axes to the run after that transient; untick “Fit y-axes after the start-up transient” above the plots to see it.
walkthrough-step4-plot-title = Step 4: z4, v4 and the voltage before and after the limit
walkthrough-step4-plot2-title = Step 4: d̃4 evaluated from the simulated truth, against ±h4
walkthrough-step4-plot3-title = Step 4: ż4 as the run made it (its change over each sample, over Ts) against the designed −k4·z4 − z3 (with its robust term when robust=1)
walkthrough-law-4-intro = Derive v4 yourself and write it below as a formula of this section’s names (v3 and z4 (from step 3), dx4h and dx5h, dxt2 and dxt3, si2 to si5, l41 to l52, a5, a7, a8, a10, k3, k4, z3; the full list is below), with + − * / ^, parentheses and functions. It runs at 20 kHz in place of the paper’s (49) as soon as you press Enter or pause; an empty field gives the paper’s law back. With your own v3 under step 3, your v4 is judged on it: it must differentiate your v3, with the ż3 your v3 gives. After the run, the verdict checks your law against the designed dynamics ż4 = −k4·z4 − z3 at drawn states and parameter values, and the plot below shows its residual over the run: zero for a law that gives them.
walkthrough-law-4-plot-title = Step 4: your law’s residual, ż4 against the designed ż4 = −k4·z4 − z3 (your v4 less the v4 that gives it: the paper’s, or after your own v3 the one that differentiates yours)

## Section stability (walkthrough-text.js): 8. Stability: Theorem 4.6

walkthrough-stability-title = 8. Stability: Theorem 4.6
walkthrough-stability-prose-1 = With V = ½(z1² + z2² + z3² + z4²) (58), the four designed error dynamics give V̇ = −k1z1² − k2z2² − k3z3² − k4z4² + z2(v2s2 + d̃2) + z4(v4s2 + d̃4) (60). The cross terms ±z1z2 and ±z3z4 cancel: that is what the −z1 in v2a and the −z3 in v4a are for.
walkthrough-stability-prose-2 = Three lines finish the proof. First, if |d̃2| ≤ h2 (h2 = δ_d2 of (38), a bound on d̃2 that the paper asserts exists given Assumption 4.2’s bounds on x̃ (22), and does not derive: d̃2 is linear in x̃1, x̃4, x̃5 with coefficients that hold the true x1, x4, x5, the estimates and the gains l11, l12, so bounds on x̃ bound it only while those stay bounded), Young’s inequality bounds the robust pair: z2(v2s2 + d̃2) ≤ h2|z2| − h2²z2²/(4ε2) ≤ ε2, since the difference is a perfect square. The same holds for z4 with h4 and ε4. Second, Σk_i·z_i² ≥ min(k_i)·Σz_i² = 2·min(k_i)·V = λV. So V̇ ≤ −λV + ε with ε = ε2 + ε4. Third, the comparison step: e^(λt)·V has the rate e^(λt)·(V̇ + λV) ≤ ε·e^(λt); integrating from 0 to t gives (59).
walkthrough-stability-prose-3 = V adds squares of different units (z1 in rad/s, z2 in rad/s², z3 in Wb², z4 in Wb²/s), and ε2 (rad²/s⁵) and ε4 (Wb⁴/s³) differ too: (59) holds for the SI numbers. It does not carry over to every weighting as it stands: with V = ½Σw_i·z_i² the cross terms of V̇ become (w1 − w2)·z1z2 and (w3 − w4)·z3z4, which cancel only for w1 = w2 and w3 = w4 (unequal weights leave a cross term, which lowers λ), unless the couplings −z1 of (35) and −z3 of (50) are rescaled to −(w1/w2)·z1 and −(w3/w4)·z3. Those couplings carry a unit (1/s² in SI) that the plain sum hides. It bounds the sum, and each ½z_i² only through the sum. The plot compares the recorded V with that bound for this run.
walkthrough-stability-prose-4 = The theorem bounds the errors z_i of the estimates, not the motor: the true speed error is |x1 − ω_d| ≤ |z1| + |x̃1|. It assumes |d̃2| ≤ h2 and |d̃4| ≤ h4 along the whole run; those bounds themselves presume x, x̂ and L bounded, which is what the theorem concludes, and the neglected L̇ terms are in neither ψ nor d̃. It says nothing about the true motor when the assumption fails.
walkthrough-stability-shows-1 = With the EKF’s 10 % initial error and an exact model the voltage limit holds the start-up: sine200 runs away on { $wt-limit-runaway } of { $wt-limit-runaway--draws } draws with it (with the motor’s R_r 10 % above the model’s, on { $wt-limit-rrhigh-runaway } even with it), but without it (vmax=100000) on { $wt-nolimit-runaway }, ending up to { $wt-nolimit-off-max } rad/s off with the flux at up to { $wt-nolimit-flux-max } Wb. From a correct initial estimate (init_err=0) the same run without the limit tracks to { $wt-exact-rms-min } to { $wt-exact-rms-max } rad/s RMS on every draw with an exact model; with the motor’s R_r 10 % above the model’s it fails even so: its RMS error is at least { $wt-exact-rrhigh-rms } rad/s, and it runs away on { $wt-exact-rrhigh-runaway } of { $wt-exact-rrhigh-runaway--draws } draws.
walkthrough-stability-plot-title = Lyapunov function V(t) = ½Σz_i² against the bound (59), log scale

## The plots' signals, in their legends (walkthrough-text.js, walkthrough-laws.js)

# $signal is a symbol, e.g. ω̂ or |φ̂|.
walkthrough-series-estimated = { $signal } estimated
# $signal is a symbol, e.g. ω or |φ|.
walkthrough-series-true = { $signal } true
# A signal drawn on the right-hand axis: $signal is a symbol, e.g. P₁₁.
walkthrough-series-right = { $signal } (right)
# A signal drawn on the right-hand axis: $signal is a symbol (z1), $unit its unit (rad/s).
walkthrough-series-right-unit = { $signal } ({ $unit }, right)
# The part of a step's virtual control that cancels the known terms: $term is a symbol, e.g. v1a.
walkthrough-series-feedforward = { $term } feedforward
# The part of a step's virtual control that feeds its error back: $term is a symbol, e.g. v1s.
walkthrough-series-feedback = { $term } feedback
# A step's error rate as the run made it: $signal is a symbol, e.g. ż1.
walkthrough-series-run = { $signal }, the run’s
# A step's error rate as its design asks: $expression is a formula, e.g. −k1·z1 + z2.
walkthrough-series-designed = { $expression }, designed
# The motor's load torque: the constant T0 plus the load step.
walkthrough-series-load-true = T_L true (T0 + step)
walkthrough-series-rr-motor = R_r of the motor
walkthrough-series-u-commanded = u_sa commanded (V)
walkthrough-series-u-applied = u_sa applied (V)
walkthrough-series-lyapunov = V(t) Lyapunov function
# The bound of the paper's equation (59).
walkthrough-series-bound = bound (59)
# The residual of a student's own law in steps 1 and 3: $output is the law's output, v1 or v3.
walkthrough-series-law-paper = your { $output } − the paper’s { $output }
# The residual of a student's own law in steps 2 and 4: $output is v2 or v4, $rate ż2 or ż4.
walkthrough-series-law-gives = your { $output } − the { $output } that gives { $rate }
# The lines of the NIS plot's 95 % band.
walkthrough-nis-low = 2.5 % quantile
walkthrough-nis-high = 97.5 % quantile
# The unit of the Lyapunov function's axis.
walkthrough-stability-plot-unit = V (mixed units: ½Σz_i²)

## A section's frame (walkthrough-sections.js, walkthrough.js)

# The name of a diagram's scroll box for screen readers: $section is the section's title, e.g.
# “3. From the observer to the controller: (4) and (5)”.
walkthrough-diagram-label = Diagram of section { $section }
# The name of an equation's scroll box for screen readers: $number counts the section's equations
# from 1, $section is the section's title.
walkthrough-equation-label = Equation { $number } of section { $section }
walkthrough-run-shows = What the run shows
walkthrough-lumped-label = Lumped parameters of the plant and the model
# The rows of the lumped-parameter table: the simulated motor, and what the EKF and the controller
# assume.
walkthrough-lumped-plant = plant
walkthrough-lumped-model = model
walkthrough-stability-waiting = Run a scenario to compare V with the bound.
walkthrough-compare-button = Compare Euler and RK4 predictors on this scenario
walkthrough-compare-label = Euler and RK4 predictors compared
walkthrough-knobs = Design knobs
walkthrough-ifoc-note = This scenario runs the classical IFOC baseline. The backstepping terms below are evaluated from the EKF estimate for comparison; they are not what drives the motor.
walkthrough-equations-failed = The equations could not be loaded: check the connection and open the walkthrough again.

## The stability report (walkthrough-reports.js): the bound (59) against V over the run, then
## what it adds when V leaves the bound, by the likely cause. Its sentences are shown one after
## the other, parted by a space.

walkthrough-stability-nothing = Nothing was recorded.
# The bound of the run: $lambda its rate in 1/s (2400), $eps the sum ε2 + ε4 of the robust terms
# (0.002).
walkthrough-stability-bound-robust = λ = 2·min(k) = { $lambda } 1/s, ε = { $eps } (robust terms on).
# The same without the robust terms ($eps is 0).
walkthrough-stability-bound-off = λ = 2·min(k) = { $lambda } 1/s, ε = { $eps } (robust terms off, so the bound is V(0)·e^(−λt)).
# $samples is the run's number of samples.
walkthrough-stability-under =
    V stays under the bound at { $samples ->
        [one] its only sample
       *[other] all { $samples } samples
    }.
# $outside counts the samples where V is above the bound, of the run's $samples; $first is the
# time of the first (0.00005); $outsideSaturated counts those with the voltage at its limit, and
# $saturated all the samples with the voltage at its limit.
walkthrough-stability-above =
    V is above the bound at { $outside } of { $samples ->
        [one] { $samples } sample
       *[other] { $samples } samples
    }, first at t = { $first } s; { $outsideSaturated } of them with the voltage saturated ({ $saturated ->
        [one] { $saturated } sample is saturated in all
       *[other] { $saturated } samples are saturated in all
    }).
walkthrough-stability-cause-saturation = Most of those samples have a commanded voltage beyond the limit: saturation breaks the designed error dynamics the bound relies on.
walkthrough-stability-cause-sampling = With the perfect observer and an exact model d̃2 = d̃4 = 0, and in continuous time V would stay under the bound (on it, with equal gains). The sampled loop leaves an error of its own, of the order of Ts in the z_i: on decay V stops at a floor while the bound falls on, so that V ends far above it, and halving Ts scales the floor by { $wt-decay-halfts }. A rotor-resistance error adds a disturbance of its own, far above that floor: with the motor’s R_r 10 % above and below the model’s, V ends decay at { $wt-decay-rrhigh } and { $wt-decay-rrlow } times it. An inertia error does not on decay: with the model’s inertia 20 % above and below the motor’s (model.j = 0.024 and model.j = 0.016), V ends at { $wt-decay-jhigh } and { $wt-decay-jlow } times the floor.
walkthrough-stability-cause-estimation-errors = The estimation errors enter as d̃2 and d̃4; with the robust terms off nothing bounds z2·d̃2 + z4·d̃4, so the bound (which then assumes d̃ = 0) need not hold.
walkthrough-stability-cause-eps-or-sampling = ε is too small for the actual d̃2, d̃4, or the 20 kHz sampling adds an error the continuous-time proof does not have.

## The EKF's predictors compared (walkthrough-reports.js)

# $from is the time the figures start from, the end of the start-up transient, in s (0.0207).
walkthrough-compare-note = Same scenario and seed, only the EKF predictor differs; figures from t = { $from } s on, the end of the start-up transient, as in the figures strip.
# The table's column headers; its rows are named by the predictor's setting (euler, rk4).
walkthrough-compare-predictor = predictor
walkthrough-compare-tracking = tracking RMS (rad/s)
walkthrough-compare-speed = speed-estimate RMS (rad/s)
walkthrough-compare-flux = flux-estimate RMS (Wb)
walkthrough-compare-nis = mean NIS
walkthrough-compare-saturated = samples at the voltage limit
