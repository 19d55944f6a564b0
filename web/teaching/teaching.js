// Teaching content: the seven walkthrough sections, the stability section's notes and the lessons. Prose and equations only;
// every number shown next to them comes from the core.
const t = String.raw;

// Each section: prose paragraphs, display equations (TeX), the plot of its live signals
// ([column, label, 'y2' for the right axis]) and the scenario fields that are its design knobs.
export const SECTIONS = [
  {
    id: 'model',
    title: '1. The motor model (2)',
    prose: [
      'The state is the rotor speed ω = x1, the stator currents i_sa, i_sb = x2, x3 and the rotor fluxes φ_ra, φ_rb = x4, x5 in the stationary a–b frame. Only the currents are measured; the voltages u1, u2 are the inputs.',
      'The torque over the inertia is a1(x3·x4 − x2·x5), in rad/s²: current crossed with flux (a1 = 3n_pM/(2JL_r) already contains 1/J, so multiply by J for N m). The load a2 + a3·x1 is the constant T0 and the friction Cf·ω over J. The lumped parameters below are computed by the core from the motor parameters in use; the plant (the simulated motor) and the model (what the EKF and controller assume) can differ.',
    ],
    equations: [
      t`\dot x_1 = a_1(x_3x_4 - x_2x_5) - a_2 - a_3x_1`,
      t`\dot x_2 = a_5x_4 + a_6x_1x_5 - a_7x_2 + b\,u_1,\quad \dot x_3 = a_5x_5 - a_6x_1x_4 - a_7x_3 + b\,u_2`,
      t`\dot x_4 = -a_8x_4 - a_9x_1x_5 + a_{10}x_2,\quad \dot x_5 = -a_8x_5 + a_9x_1x_4 + a_{10}x_3`,
      t`\sigma = L_s - \tfrac{M^2}{L_r},\ \alpha = \tfrac{R_r}{L_r},\ \beta = \tfrac{M}{\sigma L_r},\ a_1 = \tfrac{3n_pM}{2JL_r},\ a_5 = \alpha\beta,\ a_6 = n_p\beta,\ a_7 = \tfrac{R_s}{\sigma} + \alpha\beta M,\ a_8 = \alpha,\ a_9 = n_p,\ a_{10} = \alpha M,\ b = \tfrac1\sigma`,
    ],
    lumped: true,
    plot: {
      title: 'Speed and flux',
      unit: 'rad/s',
      unit2: 'Wb',
      series: [
        ['omega', 'ω (rad/s)'],
        ['flux', '|φ| (Wb, right)', 'y2'],
      ],
    },
    knobs: ['plant.rr', 'model.rr', 'load.torque'],
  },
  {
    id: 'ekf',
    title: '2. The extended Kalman filter (10)–(20)',
    prose: [
      'The EKF estimates all five states from the measured currents and the applied voltages. It predicts with the model discretised by forward Euler (10), linearised by the Jacobian (11), and corrects with the innovation: the measured minus the predicted currents.',
      'Q (process noise: q·Ts on every state, plus q_speed·Ts on the speed alone) says how much the model is trusted; R (measurement noise, r_std²·I) how much the sensors are. One q for states of mixed units is the paper’s choice; q_speed lets the speed estimate move without loosening the rest. The gain K_k enters the controller as the observer gain L = K_k/Ts of the general form (4): the estimation errors x̃ are what the controller must tolerate.',
      'A consistent filter has innovations inside their ±2σ band about 95 % of the time and a normalised innovation squared (NIS) averaging 2. The Euler predictor cannot follow 200 Hz currents: compare it with RK4 below.',
      'Section 3.1 names a remedy it does not build: treat slowly varying quantities as extra states. The knob ekf.load adds a2 = T_L0/J as a random walk (the controller then uses â2 and its rate, the injection l_a·(x̃2, x̃3)); ekf.rr adds the rotor resistance (the controller’s a5, a7, a8, a10 follow R̂_r). The last two plots show both estimates with their ±2σ bands from P against the truth. An extra state absorbs whatever the model lacks, right or wrong: a rotor-resistance state under an unknown load takes the load for a resistance (see the lessons).',
    ],
    equations: [
      t`\hat x_{k|k-1} = \hat x_{k-1|k-1} + T_s f(\hat x_{k-1|k-1}, u_{k-1}),\qquad A_{k-1} = I + T_s \tfrac{\partial f}{\partial x}\Big|_{\hat x_{k-1|k-1}}`,
      t`P_{k|k-1} = A_{k-1}P_{k-1|k-1}A_{k-1}^T + Q,\qquad \tilde y_k = y_k - C\hat x_{k|k-1},\qquad S_k = CP_{k|k-1}C^T + R`,
      t`K_k = P_{k|k-1}C^TS_k^{-1},\qquad \hat x_{k|k} = \hat x_{k|k-1} + K_k\tilde y_k,\qquad L = K_k/T_s`,
      t`P_{k|k} = (I - K_kC)P_{k|k-1}(I - K_kC)^T + K_kRK_k^T\quad\text{(Joseph form of (19))}`,
    ],
    plot: {
      title: 'Innovation ỹ_a with its ±2σ band from S_k',
      unit: 'A',
      series: [
        ['innov_a', 'ỹ_a'],
        ['innov_band_a', '+2σ'],
        ['innov_band_a', '−2σ', null, -1],
      ],
    },
    plot4: {
      title: 'Normalised innovation squared with its 95 % band (χ², 2 dof)',
      unit: 'NIS',
      series: [['nis', 'NIS']],
      nisBand: true,
    },
    plot2: {
      title: 'Speed estimate and its variance',
      unit: 'rad/s',
      unit2: '(rad/s)²',
      series: [
        ['omega_hat', 'ω̂ estimated'],
        ['omega', 'ω true'],
        ['p_omega', 'P₁₁ (right)', 'y2'],
      ],
    },
    plot3: {
      title: 'Flux modulus: true and estimated',
      unit: 'Wb',
      series: [
        ['flux_hat', '|φ̂| estimated'],
        ['flux', '|φ| true'],
      ],
    },
    // The remedies of Section 3.1: with ekf.load=1 or ekf.rr=1 the estimate moves, with its ±2σ
    // band from P; otherwise it is the model's fixed value against the truth.
    plot5: {
      title: 'Load torque: estimate â2·J with its ±2σ band, and the truth',
      unit: 'N m',
      series: [
        ['load_band', 'T̂_L + 2σ', null, 1, 'load_hat'],
        ['load_band', 'T̂_L − 2σ', null, -1, 'load_hat'],
        ['load_hat', 'T̂_L estimated'],
        ['load', 'T_L true (T0 + step)'],
      ],
    },
    plot6: {
      title: 'Rotor resistance: estimate with its ±2σ band, and the motor’s',
      unit: 'Ω',
      series: [
        ['rr_band', 'R̂_r + 2σ', null, 1, 'rr_hat'],
        ['rr_band', 'R̂_r − 2σ', null, -1, 'rr_hat'],
        ['rr_hat', 'R̂_r estimated'],
        ['rr', 'R_r of the motor'],
      ],
    },
    knobs: ['ekf', 'ekf.q', 'ekf.q_speed', 'ekf.r_std', 'ekf.load', 'ekf.q_load', 'ekf.rr', 'ekf.q_rr'],
    compare: true,
  },
  {
    id: 'step1',
    title: '3. Step 1: the speed loop',
    prose: [
      'Step 1 regulates the estimated speed: z1 = x̂1 − ω_d. Its virtual control is the torque term a1(x3·x̂4 − x2·x̂5), built from measured currents and estimated fluxes; v1 is the torque over the inertia (rad/s²) that Step 1 asks for, and z2 is how far the actual torque term is from it.',
      'The feedforward v1a cancels the modelled load, the reference acceleration and the observer injection si1 = l11·x̃2 + l12·x̃3 (a measured residual, hence known). The feedback v1s = −k1s1·z1 with k1 = a3 + k1s1 makes ż1 = −k1·z1 + z2.',
    ],
    equations: [
      t`z_1 = \hat x_1 - \omega_d,\qquad z_2 = a_1(x_3\hat x_4 - x_2\hat x_5) - v_1`,
      t`v_1 = v_{1a} + v_{1s},\quad v_{1a} = -s_{i1} + \dot\omega_d + a_3\omega_d + \hat a_2,\quad v_{1s} = -k_{1s1}z_1`,
      t`\dot z_1 = -k_1z_1 + z_2,\qquad k_1 = a_3 + k_{1s1}`,
      t`\dot v_1 = k_{1s1}k_1z_1 - k_{1s1}z_2 + (l_{11}a_7 + l_{11}l_{21} + l_{12}l_{31})\tilde x_2 + (l_{12}a_7 + l_{11}l_{22} + l_{12}l_{32})\tilde x_3 + \ddot\omega_d + a_3\dot\omega_d + \dot{\hat a}_2 + \ldots`,
    ],
    note: 'Printed (31) has a3·ω_d and â2 where a3·ω̇_d and dâ2/dt belong (corrected above); the “…” are the x̃1, x̃4, x̃5 terms, which go into d̃2.',
    plot: {
      title: 'Step 1: z1, v1 = v1a + v1s and the torque term',
      unit: 'rad/s²',
      unit2: 'rad/s',
      series: [
        ['v1', 'v1'],
        ['v1a', 'v1a feedforward'],
        ['v1s', 'v1s feedback'],
        ['torque_hat', 'a1(x3x̂4 − x2x̂5)'],
        ['z1', 'z1 (rad/s, right)', 'y2'],
      ],
    },
    knobs: ['k1'],
  },
  {
    id: 'step2',
    title: '4. Step 2: the torque loop',
    prose: [
      'Step 2 makes the torque term follow v1 by driving z2 to zero, and here the voltages appear for the first time: v2 = b·a1(x̂4·u2 − x̂5·u1).',
      'ψ2 collects everything known: the flux and current dynamics, the observer injections si4, si5 and the derivative of v1. The estimation errors x̃1, x̃4, x̃5 enter only through d̃2, which is unknown and left out; the robust term v2s2 = −h2²z2/(4ε2) can dominate it if its bound h2 is known.',
      'Differentiating z2 also gives −(a7 + a8)·z2, a damping the motor supplies itself; (32) as printed drops it, and the k2 = a7 + a8 + k2s1 of (36) counts it.',
    ],
    equations: [
      t`\dot z_2 = v_2 + \psi_2 - (a_7 + a_8)z_2 + \tilde d_2,\qquad v_2 = b\,a_1(\hat x_4u_2 - \hat x_5u_1)`,
      t`\psi_2 = -(a_7 + a_8)v_1 - a_1a_6\hat x_1(\hat x_4^2 + \hat x_5^2) - a_1a_9\hat x_1(\hat x_5x_3 + \hat x_4x_2) + a_1a_{10}(\hat x_2x_3 - \hat x_3x_2) + a_1(x_3s_{i4} - x_2s_{i5}) - \dot v_1`,
      t`v_2 = v_{2a} + v_{2s},\quad v_{2a} = -\psi_2 - z_1,\quad v_{2s} = -k_{2s1}z_2 - \tfrac{h_2^2}{4\epsilon_2}z_2,\quad k_2 = a_7 + a_8 + k_{2s1}`,
      t`\dot z_2 = -k_2z_2 - z_1 + v_{2s2} + \tilde d_2`,
    ],
    plot: {
      title: 'Step 2: z2 and v2 = v2a + v2s',
      unit: 'rad/s³',
      unit2: 'rad/s²',
      series: [
        ['v2', 'v2'],
        ['v2a', 'v2a feedforward'],
        ['v2s', 'v2s feedback'],
        ['z2', 'z2 (rad/s², right)', 'y2'],
      ],
    },
    knobs: ['k2', 'robust', 'eps2', 'h2'],
  },
  {
    id: 'step3',
    title: '5. Step 3: the flux outer loop',
    prose: [
      'Step 3 regulates the estimated flux modulus squared: z3 = x̂4² + x̂5² − ψ_d. Its virtual control is 2a10(x2·x̂4 + x3·x̂5), the part of ż3 the stator currents drive.',
      'ψ3 depends only on estimates and measured residuals, so Step 3 has no unknown term at all: with v3 = −ψ3 − k3·z3, ż3 = −k3·z3 + z4 holds exactly in continuous time, for the observer’s own flux estimate. The sampled loop meets it only approximately, and the measurement noise enters through the innovations: on step with an exact model, from 15 ms on (after the start-up), the recorded z3 misses it by 71 to 73 % of the RMS of ż3 over seeds 1–10, by 9.3 % without noise (noise=0) and by 2.7 % with the perfect observer (perfect=1), whose miss halves with Ts. The z3 plot shows the estimate’s error, not the motor’s.',
    ],
    equations: [
      t`z_3 = \hat x_4^2 + \hat x_5^2 - \psi_d,\qquad \dot z_3 = 2a_{10}(x_2\hat x_4 + x_3\hat x_5) + \psi_3`,
      t`\psi_3 = -2a_8(\hat x_4^2 + \hat x_5^2) - 2a_{10}(\tilde x_2\hat x_4 + \tilde x_3\hat x_5) + 2\hat x_4s_{i4} + 2\hat x_5s_{i5} - \dot\psi_d`,
      t`v_3 = v_{3a} + v_{3s},\quad v_{3a} = -\psi_3,\quad v_{3s} = -k_3z_3,\qquad z_4 = 2a_{10}(x_2\hat x_4 + x_3\hat x_5) - v_3`,
      t`\dot z_3 = -k_3z_3 + z_4`,
    ],
    plot: {
      title: 'Step 3: z3 and v3 = v3a + v3s',
      unit: 'Wb²/s',
      unit2: 'Wb²',
      series: [
        ['v3', 'v3'],
        ['v3a', 'v3a feedforward'],
        ['v3s', 'v3s feedback'],
        ['z3', 'z3 (Wb², right)', 'y2'],
      ],
    },
    knobs: ['k3', 'psi_d'],
  },
  {
    id: 'step4',
    title: '6. Step 4: the flux inner loop and the voltages',
    prose: [
      'Step 4 drives z4 to zero; its input v4 = 2a10·b(x̂4·u1 + x̂5·u2) is the second combination of the voltages. ψ4 is long but known: the current and flux dynamics of the observer, the nominal residual dynamics and k3(−k3z3 + z4) from differentiating v3. d̃4 again collects the unmeasurable estimation errors.',
      'v2 and v4 together fix both voltages through the decoupling matrix (54), which is invertible while the estimated flux is not zero (55). The voltage limit then acts: the paper’s ±400 V box clips each component, while the circle and the inverter’s hexagon (vlimit) scale the whole vector down, keeping its direction. While it acts, the designed error dynamics no longer hold.',
    ],
    equations: [
      t`\dot z_4 = v_4 + \psi_4 + \tilde d_4,\qquad v_4 = a_{41}bu_1 + a_{42}bu_2,\quad a_{41} = 2a_{10}\hat x_4,\ a_{42} = 2a_{10}\hat x_5`,
      t`v_4 = v_{4a} + v_{4s},\quad v_{4a} = -\psi_4 - z_3,\quad v_{4s} = -k_4z_4 - \tfrac{h_4^2}{4\epsilon_4}z_4,\qquad \dot z_4 = -k_4z_4 - z_3 + v_{4s2} + \tilde d_4`,
      t`\begin{bmatrix}u_1\\u_2\end{bmatrix} = \frac1b\begin{bmatrix}-a_1\hat x_5 & a_1\hat x_4\\ 2a_{10}\hat x_4 & 2a_{10}\hat x_5\end{bmatrix}^{-1}\begin{bmatrix}v_2\\v_4\end{bmatrix},\qquad \det = -2a_1a_{10}(\hat x_4^2 + \hat x_5^2) \ne 0`,
    ],
    note: 'Printed (48) has a21, a22 where a41, a42 belong (corrected above). In the first milliseconds the start-up transient commands tens of kilovolts, 11 to 32 kV at its peak on step and 34 to 166 kV on rr-mismatch over seeds 1–10, and on rr-mismatch it stays beyond the limit for the first 10 to 19 ms; the limit clips it. The plots fit their y-axes to the run after that transient; untick “Fit y-axes after the start-up transient” above the plots to see it.',
    plot: {
      title: 'Step 4: z4, v4 and the voltage before and after the limit',
      unit: 'V',
      unit2: 'Wb²/s',
      series: [
        ['u_a_cmd', 'u_sa commanded (V)'],
        ['u_a', 'u_sa applied (V)'],
        ['z4', 'z4 (Wb²/s, right)', 'y2'],
      ],
    },
    knobs: ['k4', 'robust', 'eps4', 'h4', 'vmax'],
  },
  {
    id: 'stability',
    title: '7. Stability: Theorem 4.6',
    prose: [
      'With V = ½(z1² + z2² + z3² + z4²), the four designed error dynamics give V̇ = −k1z1² − k2z2² − k3z3² − k4z4² + z2(v2s2 + d̃2) + z4(v4s2 + d̃4). The cross terms ±z1z2 and ±z3z4 cancel: that is what the −z1 in v2a and the −z3 in v4a are for.',
      'If the robust terms keep z2(v2s2 + d̃2) ≤ ε2 and z4(v4s2 + d̃4) ≤ ε4, then V̇ ≤ −λV + ε and V stays under the bound (59). The plot compares the recorded V with that bound for this run.',
      'The theorem is about the errors z_i of the estimates: it assumes the estimation errors stay small enough for d̃2, d̃4 to be bounded, and says nothing about the true motor when they are not. With the EKF’s 10 % initial error only the voltage limit holds the start-up: without it (sine200 with vmax=100000) the run ends 6,100 to 6,500 rad/s off, on either side, with the flux at 8.7 to 9.3 Wb over seeds 1–10, and the page reports it as a run that ran away. From a correct initial estimate (init_err=0) the same run tracks to 0.013 to 0.014 rad/s RMS with an exact model, but with the motor’s R_r 10 % above the model’s it fails even so.',
    ],
    equations: [
      t`V_s = \tfrac12(z_1^2 + z_2^2 + z_3^2 + z_4^2),\qquad \dot V_s \le -\lambda V_s + \epsilon,\qquad \lambda = 2\min(k_1,k_2,k_3,k_4),\ \epsilon = \epsilon_2 + \epsilon_4`,
      t`V_s(t) \le e^{-\lambda t}V_s(0) + \frac{\epsilon}{\lambda}\left(1 - e^{-\lambda t}\right)\qquad (59)`,
    ],
    plot: {
      title: 'Lyapunov function V(t) = ½Σz_i² against the bound (59), log scale',
      unit: 'V (mixed units: ½Σz_i²)',
      log: true,
      series: [
        ['lyapunov', 'V(t) Lyapunov function'],
        ['lyapunov_bound', 'bound (59)'],
      ],
    },
    knobs: ['robust', 'eps2', 'h2', 'eps4', 'h4'],
    stability: true,
  },
];

// What the stability section adds when V leaves the bound (59), by the core's most likely cause.
export const STABILITY_CAUSES = {
  saturation:
    'Most of those samples have a commanded voltage beyond the limit: saturation breaks the designed error dynamics the bound relies on.',
  sampling:
    'With the perfect observer and an exact model d̃2 = d̃4 = 0, and in continuous time V would stay under the bound (on it, with equal gains). The sampled loop leaves an error of its own, proportional to Ts in the z_i: on decay V stays under the bound for about the first 5 ms, then stops at a floor, reached by about 15 ms, while the bound falls on, so that V ends about 10¹¹ times above it; halving Ts quarters the floor. A model that differs from the motor adds a d̃ of its own, far above that floor (10⁶ times with the motor’s R_r 10 % off either way).',
  estimation_errors:
    'The estimation errors enter as d̃2 and d̃4; with the robust terms off nothing bounds z2·d̃2 + z4·d̃4, so the bound (which then assumes d̃ = 0) cannot hold.',
  eps_or_sampling:
    'ε is too small for the actual d̃2, d̃4, or the 20 kHz sampling adds an error the continuous-time proof does not have.',
};

// Guided lessons: the run a lesson opens (a preset, with overrides where the lesson needs a
// longer run or another setting), what to look for, a question that the page's figures answer,
// a hint, and the answer for the lecturer. Every number in a lesson's text is checked against
// the core by tests/lessons.test.mjs, which names the run each one comes from. A lesson's `id` is
// its link's name (`#lesson=ID`), which never changes: a link to a lesson outlives lessons added
// or reordered.
export const LESSONS = [
  {
    id: 'step-response',
    run: 'v=1&preset=step',
    title: 'The paper’s step response',
    look: 'A 0.5 rad/s step, filtered by a critically damped 200 Hz filter, starts at 50 ms. Drag across 45–65 ms on the speed plot: the true speed follows the filtered reference. The ω − ω_d plot shows the error during the step; the figures strip gives the 2 % settling time and the peak error over the preset’s 0.1 s.',
    question:
      'The reference filter alone settles (to 2 %) in 4.6 ms. What is the 2 % settling time of the true speed, and how much does the controller with its observer add? Does that hold if the model’s inertia is off?',
    hint: 'Read “2 % settling time of ω after the step” in the figures strip and subtract the filter’s 4.6 ms; change the noise seed (settings, Noise and seed) and read it again. Then set model.j = 0.024 (the model’s inertia 20 % high) in the settings and run again.',
    answer:
      'The true speed settles in 4.70 to 4.75 ms over seeds 1–10, two to three samples more than the filter’s 4.6 ms, but with an exact model only: with the model’s inertia 20 % off either way, or the motor’s rotor resistance 10 % off either way, the preset’s 0.1 s ends with no settling time. The tracking is the feedforward’s: the controller feeds ω̇_d and ω̈_d forward, and halving k1 to 600 leaves the settling time at 4.70 to 4.75 ms. With the model’s inertia 20 % high (model.j = 0.024) the EKF predicts the wrong acceleration and the controller tracks a wrong estimate: at the end of the 0.1 s the speed is still 0.022 rad/s off on every seed, almost all of it the estimate’s error, and over 1 s (duration=1) it enters the 2 % band for good 75 to 77 ms after the step. The controller alone would not mind: with the same wrong inertia and a perfect observer (perfect=1) it settles in 3.35 ms. With the motor’s rotor resistance 10 % high (plant.rr=5.445) the filter loses the speed at this low speed, which ends 3.4 to 27 rad/s off, depending on the noise draw (see the lesson on low speed).',
  },
  {
    id: 'tracking-200hz',
    run: 'v=1&preset=sine200-1rad',
    title: 'Why 200 Hz tracking needs a small amplitude',
    look: 'Doubling the 200 Hz sine to 1 rad/s doubles the torque, and so the current and voltage the drive needs. The voltage plot sits on ±400 V for part of each period. Over the preset’s 0.25 s after the start-up transient, the figures strip gives the share of samples at the limit, the tracking error and the peak stator current against the motor’s 4 A rating.',
    question:
      'What share of samples is at the voltage limit, and does it stay so over a longer run (duration = 2)? How does the RMS of ω − ω_d compare with the 0.5 rad/s run (preset sine200)? Which limit does the motor reach first: the voltage or the current?',
    hint: 'Note the figures, then pick sine200 in the preset picker (or press Previous and come back) and read them again. Compare “peak stator current” with the rated 4 A, then drag across the current plot from 50 ms on: do the currents stay past it?',
    answer:
      'At 200 Hz the current passes the motor’s rating well before the voltage limit matters, and doubling the amplitude roughly quadruples the tracking error, mostly through the Euler predictor and not the clipping. All of this holds for an exact model only. In the strip over seeds 1–10, at 1 rad/s 16 to 17 % of the samples are at the limit and the RMS of ω − ω_d is 0.063 to 0.066 rad/s; at 0.5 rad/s no sample is at the limit and the RMS is 0.016 to 0.018 rad/s, 3.6 to 4.0 times less. The quadrupling is not because of the clipping: without any limit (vmax=100000, from a correct initial estimate, init_err=0) the ratio is 4.4 to 4.5. It comes from the Euler predictor: with RK4 and no limit the ratio is 2.0, as for a linear loop. The share at the limit is not a constant of the run: over a longer run it swings between almost none and about half of the samples, about once a second. That comes from the box’s corners: the flux turns a quarter of a revolution in about a second, and the ±400 V box looks the same every quarter turn; with a round limit (vlimit=circle) the share stays the same all through the run. The strip covers only the first quarter second; over 2 s (duration=2) the share is 32 %. The strip’s peak current is 14.3 to 16.4 A at 1 rad/s and 7.2 to 9.6 A at the paper’s 0.5 rad/s, with no sample at the voltage limit. These peaks fall in the first 8 ms, at the end of the start-up, but the current stays past the rating: from 50 ms on it still peaks at 6.6 A at 0.5 rad/s, and about 0.27 rad/s (sine.amp=0.27) is the largest 200 Hz amplitude that stays within 4 A from 50 ms on over a 1 s run. With the model off, the 0.5 rad/s run’s error is at least 3.7 times the exact model’s, with the model’s inertia 20 % high or low or the motor’s R_r 10 % below the model’s; with R_r 10 % above, both runs run away (see the lesson on low speed).',
  },
  {
    id: 'observer-bias',
    run: 'v=1&preset=sine200',
    title: 'Observer bias: Euler against RK4',
    tab: 'walkthrough',
    look: 'The mean NIS in the figures strip is shown against its 95 % band: a consistent filter has a mean of 2. Then press “Compare Euler and RK4 predictors” in the EKF section (2.) of this walkthrough. The controller is the same in both runs, over the preset’s 0.25 s.',
    question:
      'Is the paper’s Euler EKF consistent on this run? What happens to the mean NIS and the tracking RMS with the RK4 predictor?',
    hint: 'A mean NIS far outside its band means the filter’s model of its own errors is wrong; the page says so above the figures. The comparison table lists both predictors on the same scenario and seed.',
    answer:
      'No: its mean NIS is 35.4 to 35.8 over seeds 1–10, against a band of about 1.94–2.06, and its biased speed estimate makes most of the tracking error: RK4 brings the RMS of ω − ω_d from 0.016–0.018 down to 0.0062–0.0064 rad/s. That gain needs an exact model: with the model’s inertia 20 % off either way both predictors track to 0.067–0.082 rad/s RMS, with the motor’s rotor resistance 10 % below the model’s to 0.099–0.17 rad/s, and with it 10 % above neither holds the speed. With RK4 the mean NIS is 1.84–1.95, at the band’s lower edge or a little below: RK4 slightly overstates its errors. A forward-Euler prediction over one 50 µs sample misses the curvature of 200 Hz currents (at 20 Hz, sine.freq=20, the Euler filter’s mean NIS is 1.86–1.96); the filter blames the miss on the states, so the estimates the controller uses are biased. The error plot shows it: with Euler, ω − ω_d swings about a mean of 0.013–0.014 rad/s, the speed estimate’s own offset, and that offset is most of the RMS.',
  },
  {
    id: 'rr-mismatch',
    run: 'v=1&preset=rr-mismatch&duration=6',
    title: 'Rotor-resistance mismatch: a slow transient, then a small bias',
    look: 'The motor’s rotor resistance is 10 % above what the EKF and controller assume. This run holds 50 rad/s for 6 s (the preset itself stops at 0.3 s). The speed estimate reaches the reference within milliseconds, while the true speed starts well below it and creeps up over seconds. The figures strip gives the final speed error and says whether it had settled by the end of the run.',
    question:
      'How far below 50 rad/s is the true speed at 0.3 s, at 1 s, and at the end of the 6 s run, and how much of that does the noise draw decide? What does the slow recovery depend on, and why does the error end on the other side of zero?',
    hint: 'Read ω − ω_d off the error plot with the cursor at 0.3 s and 1 s, then change the noise seed (settings, Noise and seed) and read it again. Open the preset itself (rr-mismatch): its strip says its final value is still changing. For the sign, run the same 6 s with the exact model (plant.rr = 4.95), then both again with the RK4 predictor (ekf = rk4).',
    answer:
      'The 10 % error in R_r leaves a slow start-up transient, which the filter removes with a time constant of about 0.6 s, and then a small bias: the true speed ends 0.12 rad/s high on every seed. The same holds with the motor’s R_r 10 % below the model’s (plant.rr=4.455: it ends 0.30 rad/s high) and with the model’s inertia 20 % off either way (0.10 to 0.16 rad/s high). How deep the transient is depends on the noise draw: at 0.3 s the true speed is 1.2 to 5.1 rad/s low over seeds 1–10 (5.0 in this run, seed 1), at 1 s 0.19 to 1.4 rad/s low. From 20 ms on the estimate stays within 1 rad/s of the reference, so the controller is content: the error is the estimate’s. The transient comes from the start-up: from a correct initial estimate (init_err=0) the speed is only 0.06 to 0.07 rad/s high at 0.3 s. With the model’s R_r wrong the filter removes the start-up error slowly, along a direction the currents barely reveal (its mean NIS from 0.1 s to 1 s is 2.0 to 3.5); with the exact model (plant.rr = 4.95) the speed is only 0.07 to 0.49 rad/s low at 0.3 s. Neither the loop gains nor the filter’s Q and R change the time constant much; the operating point (the load T0, the flux ψ_d) and the model’s inertia do. The bias’s sign is the Euler predictor’s: with the exact model the Euler EKF alone ends 0.21 rad/s high, and the mismatch pulls −0.09 rad/s, as the RK4 runs show (−0.084 to −0.087 rad/s with the mismatch, +0.003 to +0.006 without). That pull is the slip argument: a larger R_r needs more slip for the same torque; with R_r 10 % low it pulls +0.09 rad/s.',
  },
  {
    id: 'load-step',
    run: 'v=1&preset=load-step&duration=3',
    title: 'An unknown load step',
    look: 'At 0.15 s a 2 N m load torque appears that neither the EKF nor the controller knows about. This run lasts 3 s (the preset stops at 0.3 s, in the middle of the fall). Watch the true speed and its estimate after 0.15 s, and read the final errors in the figures strip.',
    question:
      'Where does the true speed end, where does the estimate end, and how much of the loss is the controller’s and how much the observer’s?',
    hint: 'Read “final speed error ω − ω_d” and “final speed-estimate error ω − ω̂”. Then run it with a perfect observer (perfect = 1 in the Observer settings): the controller then sees the true state.',
    answer:
      'The true speed settles 25.4 rad/s below 50 rad/s while the estimate stays on the reference: the loss is the observer’s, and the controller alone would lose only 0.17 rad/s. That holds with the model off as well: with the motor’s R_r 10 % off or the model’s inertia 20 % off, either way, the speed ends 24.7 to 26.0 rad/s low, and with a perfect observer at most 0.21 rad/s low. The true speed falls for about a second (11 to 12 rad/s low at 0.3 s, 19 to 20 at 0.5 s over seeds 1–10) and settles on every seed; the estimate ends on the reference (ω − ω̂ = −25.4 rad/s) and the filter is far from consistent (mean NIS about 56). With a perfect observer (perfect = 1) the error is ΔT/J·(1/k1 + 1/k2), the droop of a design without integral action. The rest is the 5-state EKF’s: its model holds the load at a2 = T0/J, so it explains the load’s effect on the currents with a wrong speed and flux. Two remedies: make the load a state of the filter (next lesson), or let the speed estimate move faster than the model says: ekf.q_speed adds process noise to the speed state alone. At ekf.q_speed=1e7 the RMS error over the last second of the run falls to about 0.09 rad/s; at 1e6 the estimate follows too slowly (about 2.3 rad/s), at 1e8 it is too noisy (about 0.6 rad/s): the speed’s process noise trades the error for noise. That remedy holds with the model’s inertia 20 % off either way but not with the motor’s R_r 10 % off: 1e7 then leaves 0.49 rad/s with R_r above the model’s, 5.8 rad/s with it below.',
  },
  {
    id: 'load-estimate',
    run: 'v=1&preset=load-step-est',
    title: 'The remedy: the load as an EKF state',
    tab: 'walkthrough',
    look: 'The same 2 N m step at 0.15 s, this time with a2 = T_L0/J as a sixth EKF state (a random walk) and the controller using â2 and its rate. In section 2 of the walkthrough, the load-torque plot shows the estimate with its ±2σ band against the true load; compare the speed with the lesson “An unknown load step”.',
    question:
      'How far does the speed dip after the step, and what does the load estimate settle to? Why must the load be a state of the observer rather than a constant the controller is told? Does the remedy hold when the model’s rotor resistance is off?',
    hint: 'On the Trajectories tab, drag across 0.14–0.2 s on the plot “Speed tracking error ω − ω_d”: it zooms in, its y-axis fits the dip, and the cursor reads it. Then read the load-torque plot in section 2 after 0.2 s. Think about what the currents can tell the filter about the torque balance a1(x3x4 − x2x5) − a2 − a3x1 = ω̇. Last, set plant.rr = 4.455 (the motor’s R_r 10 % below the model’s) and run again.',
    answer:
      'With an exact model the speed dips by only 0.16 to 0.19 rad/s after the step and is back within 0.05 rad/s 6 to 7 ms after it, while the load estimate settles at 2.5 N m. The remedy holds with the model’s inertia 20 % off either way, but not with the motor’s rotor resistance off: 10 % above the model’s leaves a steady 0.42 rad/s low, 3 % below (plant.rr=4.8015) 2.1 rad/s RMS over the last second of a 3 s run, and 10 % below loses the speed (10 to 11 rad/s RMS, mean NIS 8,300 to 9,100). The dip shows on the zoomed error plot; the strip’s peak error also covers the start-up, the larger of the two on most seeds. The load estimate’s ±2σ band is about ±0.35 N m, its 2.5 N m is T0 = 0.5 plus the 2 N m step, and it stays there over 3 s (duration=3). A constant a2 cannot follow an unknown change; as a state with process noise, the innovation drives â2 to whatever torque balance makes the predicted currents match the measured ones, and the controller feeds â2 (and dâ2/dt, its injection) forward. The preset uses the RK4 predictor and a small Q: with the paper’s Euler predictor and Q (ekf=euler&ekf.q=0.001) the extra state takes up the predictor’s own error and the speed ends 2.8 to 3.7 rad/s low at 0.3 s. An extra state absorbs whatever the model lacks, right or wrong: give the filter the rotor resistance instead of the load (load-step with ekf.rr=1, over 3 s) and R̂_r takes up the load, ending at 5.5 Ω against the motor’s 4.95 Ω, while the speed ends 23.6 rad/s low with a mean NIS of 49.',
  },
  {
    id: 'rr-estimate',
    run: 'v=1&preset=rr-mismatch-est&duration=4',
    title: 'The remedy: the rotor resistance as an EKF state, and when it can be seen',
    tab: 'walkthrough',
    look: 'The 10 % rotor-resistance mismatch again, over 4 s, this time with R_r as an EKF state (and the RK4 predictor with a small Q). Section 2 of the walkthrough plots R̂_r with its ±2σ band against the motor’s 5.445 Ω. Then set the loads to zero: plant.t0 = model.t0 = 0 and plant.cf = model.cf = 0 in the settings, and run again.',
    question:
      'With the load, where does R̂_r go and what is left of the speed error, against the mismatch lesson’s run over the same window? Without any load or friction, what happens to R̂_r and its band, and why?',
    hint: 'At zero slip the rotor flux turns with the stator field and no current flows in the rotor: what does R_r multiply in the model then?',
    answer:
      'The R_r state removes the slow transient: at 0.3 s the speed is 0.003 to 0.012 rad/s high instead of 1.2 to 5.1 rad/s low, and within 0.05 rad/s with the motor’s R_r 10 % below the model’s instead or the model’s inertia 20 % off either way. But R̂_r is biased high, with the motor’s R_r 10 % above, equal to or 10 % below the model’s, 1.6 to 3.2 % at 4 s and 2.3 to 3.6 % at 8 s (duration=8) over seeds 1–10, so do not read it as a measurement of R_r to better than a few per cent. At 4 s the speed is 0.017 to 0.030 rad/s high, against 0.087 to 0.089 rad/s low with the same RK4 filter and no R_r state over 6 s. At 8 s the ±2σ band is about ±0.15 Ω, about as wide as the estimate’s error (0.13 to 0.20 Ω): the motor’s value sits at the band’s edge or outside it. With no load and no friction the slip is zero, the rotor current is zero, and R_r, which multiplies rotor current terms, leaves little trace in the stator currents: the band stops shrinking at about ±0.33 Ω, twice its width with the load over the same second to fourth second. R_r is well observable only with slip: load, acceleration or a flux transient.',
  },
  {
    id: 'ifoc-baseline',
    run: 'v=1&preset=ifoc-step&ref=ramp&ramp.level=40&ramp.slope=200&ramp.hold=5&ifoc.i_max=3.7&duration=1.5',
    title: 'The classical baseline, like for like: field-oriented control on the same ramp and current',
    look: 'This run uses indirect field-oriented control (IFOC) with a Schauder MRAS speed estimate, tuned by textbook rules: current loops by internal-model control (Kp = α_c·σ, Ki = α_c·R′ with R′ = R_s + (M/L_r)²R_r, α_c = 2π·1 kHz), the MRAS with both poles at −2π·50 Hz and the speed loop at 10 Hz (Kp = α_ω·J/K_t, Ki = Kp·α_ω/4). To compare like with like, both designs get the same reference, the same noise and the same current budget: a ramp at 200 rad/s² to 40 rad/s, and the IFOC’s q-current limited to 3.7 A so that |i_s| stays within the 4 A rating. Press “Pin this run”, set controller = backstepping in the settings and run: the overlay shows both.',
    question:
      'On the same ramp within 4 A, how far does each design fall behind, and how long after the ramp ends (at 0.25 s) is the IFOC within 2 % of 40 rad/s for good? What does each do with the motor’s R_r 10 % above the model’s (plant.rr = 5.445)? Which design rejects an unknown load, and why?',
    hint: 'Read “peak |ω − ω_d|” and “peak stator current” for both runs, then again with plant.rr = 5.445. For the load, open the load-step preset with load.time = 1 and duration = 2, with controller = ifoc and without.',
    answer:
      'With an exact model backstepping follows the ramp far closer than the IFOC within the same 4 A, but it survives a motor R_r at most 4 % above the model’s, where the IFOC holds with R_r 10 % off either way. Under an unknown load the order reverses: the IFOC rejects it, the paper’s 5-state design does not. With an exact model, on seeds 1–10, backstepping stays within 0.15 rad/s of the ramp at 2.8 A peak; the IFOC falls up to 7.3 rad/s behind at 4.0 A and is within 2 % (0.8 rad/s) for good 0.34 s after the ramp ends. Backstepping’s lag is its Euler EKF’s slow creep, not the ramp: with the RK4 predictor it is under half that. With the model’s inertia 20 % high or low it falls 3.6 or 3.7 rad/s behind, about half the IFOC’s lag. With the motor’s R_r above the model’s it is lost before the ramp starts, in the 50 ms at standstill under the preset’s constant load (the failure of the lesson on low speed): at 4 % high it holds on every seed from either start, at 5 % it runs away on 7 of the 10 seeds (from a correct initial estimate, init_err = 0, on none), at 7 % on all, from either start. The IFOC follows the same ramp with R_r 10 % high or low (7.7 or 6.9 rad/s behind, within 4 A), and so does backstepping with R_r 10 % low (0.8 rad/s behind). A step compares current budgets rather than designs: with an exact model, on the preset’s 40 rad/s step backstepping settles in 12 ms by drawing 43 A, 11× the rating, where the IFOC takes 0.33 s at its 20 A limit. Under an unknown load, a 2 N m step at 1 s costs the IFOC a 1.2 rad/s dip, back within 0.5 rad/s after 0.1 s with 0.09 rad/s left, while the paper’s 5-state design ends 25.4 rad/s low; with R_r 10 % or the inertia 20 % off either way, the IFOC still ends within 0.6 rad/s and the 5-state design at least 24.7 rad/s low. The IFOC’s PI speed loop has integral action; backstepping without a load state has none (the load lessons give its remedies).',
  },
  {
    id: 'real-drive',
    run: 'v=1&preset=sine200-drive&duration=1',
    title: 'Does 200 Hz survive a real drive?',
    look: 'The paper’s sine200 as a DSP drive runs it: each voltage is applied one sample after it is computed (delay = 1); the inverter makes only the hexagon of a 540 V DC link (vlimit = hex: 312 V in every direction, where the paper’s ±400 V box has 566 V corners); and it switches (pwm = 1: symmetric PWM at 20 kHz, the currents sampled at the carrier peak). This run lasts 1 s (the preset stops at 0.25 s); the figures strip gives the tracking RMS from the end of the start-up, and the current against the motor’s 4 A rating. Press “Pin this run”, then open the settings, group “Drive”, set delay.comp = 1 and run again: the pinned run is overlaid.',
    question:
      'How much larger is the RMS of ω − ω_d than on sine200 over the same 1 s, which of the three effects causes it, and how much does the delay compensation win back? What does the run cost in current, and what happens with the model’s inertia 20 % off or its rotor resistance 10 % off?',
    hint: 'Run sine200 with duration = 1, then add one effect at a time in the Drive group: delay alone, then vlimit = hex, then pwm = 1. Read “RMS of ω − ω_d” each time. For the current, drag across the current plot from 50 ms on. Then set model.j = 0.024 and 0.016, and plant.rr = 5.445 and 4.455.',
    answer:
      'The one-sample delay costs the tracking, and its compensation wins most of it back; what cannot be won back is the current, well past the rating, and the need for an almost exact model. Over the strip’s window, on seeds 1–10, the RMS of ω − ω_d is 0.015 to 0.016 rad/s on sine200 and 0.024 rad/s with the delay alone; the hexagon and PWM change it by under 1 %. The compensation (delay.comp = 1) controls from the one-step prediction x̂_(k+1|k) and brings the RMS back to 0.018 to 0.020 rad/s; with the RK4 EKF (ekf = rk4) the compensated drive tracks as well as the ideal one (0.0059 against 0.0060 rad/s). The strip’s peak current falls at the end of the start-up; from 50 ms on the current still peaks at 6.84 to 6.86 A, 1.7× the 4 A rating, and within 4 A this drive follows at most about 0.26 rad/s at 200 Hz. With the model’s inertia 20 % high or low (model.j = 0.024 or 0.016) the RMS becomes 4.0 or 2.4 times the exact model’s, because the 200 Hz tracking rests on feeding ω̇_d forward through the model’s inertia: with ω_d ≡ 0 (sine.amp = 0) the same errors change the RMS by under 0.0001 rad/s. It is the controller’s model that matters, not the observer’s: with a perfect observer the same inertia errors cost as much. With the motor’s R_r 10 % below the model’s the RMS is 0.10 to 0.11 rad/s; with it 10 % above, the run runs away, as the paper’s sine200 does (see the lesson on low speed).',
  },
  {
    id: 'high-gain',
    run: 'v=1&preset=high-gain',
    title: 'Gains past what the observer supports',
    tab: 'walkthrough',
    look: 'All four gains are 3000/s, 2.5× the paper’s. The voltage limit is hit almost all the time. The knobs k1–k4 in the Step sections and the EKF predictor and noise in the EKF section re-run the scenario when you change them; the figures strip follows, over the preset’s 0.1 s.',
    question:
      'What share of samples is at the voltage limit at 3000/s? Then try the RK4 predictor (EKF section) and, separately, noise 0 (settings, Noise and seed): which one removes the saturation, and what does that say limits the gains? Does that hold with the model off?',
    hint: 'With perfect = 1 (Observer settings) even 20,000/s works at 20 kHz, so sampling is not the limit. Change one thing at a time and read “share of samples at the voltage limit”; then set model.j = 0.024 or 0.016, or plant.rr = 4.455 or 5.445.',
    answer:
      'The Euler predictor’s model error, amplified by the gains, keeps the voltage at the limit, not the measurement noise: the RK4 predictor removes the saturation, noise 0 does not. This holds with an exact model, with the model’s inertia 20 % off either way and with the motor’s R_r 10 % below the model’s; with it 10 % above, this 0.5 rad/s step can lose the motor with either predictor. At 3000/s 99.2 to 99.6 % of the strip’s samples are at the limit on seeds 1–10, and with noise 0 still 99.4 %; with the RK4 predictor at most 0.05 %. The Euler filter’s mean NIS is 335 to 338, far outside its band: its model of its own errors is wrong, and at the paper’s 1200/s the same filter leaves no sample at the limit in the strip. With the model off as above, the Euler predictor still keeps 99 % of the samples at the limit and RK4 at most 0.05 %; with the motor’s R_r 10 % above the model’s the step runs away on 5 of the 10 seeds with the Euler predictor and on all of them with RK4 (see the lesson on low speed). Counted over the whole run, the Euler EKF’s start-up clips the voltage even at the paper’s gains: 0.7 to 1.0 % of the samples at 1200/s, all in the first 2 ms, before the strip’s window starts.',
  },
  {
    id: 'low-speed',
    run: 'v=1&preset=rr-mismatch&ref.value=1&ekf=rk4&init_err=0&duration=3',
    title: 'Where sensorless control cannot see: low speed',
    look: 'This run holds 1 rad/s for 3 s against the preset’s constant load, with the motor’s R_r 10 % above the model’s, the RK4 predictor and a correct initial estimate (ekf = rk4, init_err = 0). The paper’s own step and sine200 ask for at most 0.5 rad/s. Watch ω̂ on the speed plot and the voltage plot; the walkthrough’s EKF section plots the speed variance and the NIS.',
    question:
      'Where does the speed estimate go, what does the controller do with it, and what do the mean NIS and the peak current say? Then run it with the exact model (plant.rr = 4.95), with the motor’s R_r 10 % below the model’s (plant.rr = 4.455), and with the mismatch at ref.value = 10.',
    hint: 'Read the message above the plots, then “share of samples at the voltage limit”, “mean NIS” and “peak stator current” (under “All figures” on a small screen); the strip’s window starts about 1 s into the run. Drag across the first 40 ms of the plots to see what goes first.',
    answer:
      'With the motor’s R_r 10 % above the model’s this loop loses the motor below about 7 rad/s: the filter loses the speed, and the controller drives the motor after a speed that is not there. With R_r 10 % below the model’s it holds every speed from standstill to 15 rad/s, so at low speed the sign of the error decides. The page reports this run as ran away. The flux goes first: at 15 ms the flux estimate and the true flux are 0.05 to 0.06 Wb apart while ω̂ is still on 1 rad/s; then the estimate falls while the true flux rises, the controller, which regulates the estimate, drives the voltage to the limit at 21 ms, and only then does ω̂ leave. ω̂ ends past 2,000 rad/s while the true speed swings by up to 32 rad/s either way. In the strip’s window every sample is at the voltage limit, the peak current is 70 to 74 A on seeds 1–10 (the rating is 4 A) and the mean NIS is 160,000 to 181,000: the filter’s model no longer fits at all. The failure comes from the wrong R_r: with the exact model the same loop holds 1 rad/s to within 0.001 rad/s on seeds 1–10. The load is not why: without it (plant.t0 = model.t0 = 0, plant.cf = model.cf = 0) the run fails the same way. Over seeds 1–10, in 3 s runs with RK4 and init_err = 0: with R_r 10 % high the loop runs away at every speed up to 6.5 rad/s and holds from 7 rad/s on, with the same small bias as at 50 rad/s; 5 % high it runs away at 1 rad/s on most seeds and holds from 2 rad/s; 20 % high it still runs away at 10 rad/s and holds at 15. With R_r 10 % low it holds from 0 to 15 rad/s, ending 0.082 to 0.085 rad/s high. The speed below which the loop fails rises with the error. These runs do not show why only an R_r above the model’s fails: the usual argument, that the speed and the flux reach the stator currents through a back-EMF that shrinks with the stator frequency, says why low speed is hard, not why one sign of error fails and the other does not. The paper’s own figures are in this region: with the motor’s R_r 10 % above the model’s, step, sine200 and ramp (which starts from standstill) run away on seeds 1–10; the lesson “How exact must the model be?” maps the errors around step. The simulated motor does not saturate magnetically, so in this run its flux grows to tens of webers; a real one would saturate first.',
  },
  {
    id: 'model-exactness',
    run: 'v=1&preset=step&duration=1',
    map: 'plant.rr=-10%..+10%:11;seeds=1..10',
    tab: 'analysis',
    title: 'How exact must the model be?',
    look: 'The paper’s step (0 → 0.5 rad/s), run for 1 s, over the motor’s rotor resistance from 10 % below to 10 % above the model’s 4.95 Ω, each value with the noise seeds 1–10. The model-error map in the Analysis tab is filled in: press “Run map”. Then open the preset rr-mismatch, set plant.rr = 4.95 (the exact model) and duration = 3 in the settings, and run the same map: the same loop, holding 50 rad/s.',
    question:
      'For which errors in R_r does the paper’s step still hold, and where does it stop? Does the loop stop anywhere in the same ±10 % when it holds 50 rad/s?',
    hint: 'Choose “final speed error ω − ω_d” as the map’s figure; a cell marked ✕ ran away on that many seeds, and a click opens its run. The stator frequency is how fast the currents turn: at 50 rad/s read the period of i_sa off the current plot; at 0.5 rad/s it is longer than the 1 s run.',
    answer:
      'The paper’s step holds only while the motor’s R_r is at most 4 % above the model’s: from 6 % above on it runs away on every seed. “Holds” means only that no seed ran away: at 4 % above, the speed still ends 0.033 to 0.034 rad/s low, over a hundred times the exact model’s error. With the motor’s R_r below the model’s it never runs away and ends with a bias that grows with the error, 0.082 rad/s at 10 % below. Holding 50 rad/s, the same loop holds the whole ±10 % on every seed and ends within 0.4 rad/s of the reference. The currents turn at 0.42 Hz at 0.5 rad/s against 16 Hz at 50 rad/s. The usual argument fits this pair: the EKF reads the speed from the back-EMF, which grows with that frequency, so at low stator frequency it tells the filter little against a wrong R_r. The maps do not test that argument, and the tolerance is not a function of the speed alone: holding 20 rad/s the loop runs away with the motor’s R_r 10 % high on every seed and already 4 % high on some, worse than at 0.5 rad/s, and only holding 40 rad/s does it keep the whole +10 %. At 20 rad/s the start-up decides: from a correct initial estimate (init_err = 0) the same loop holds the motor’s R_r 10 % high on every seed. The paper’s three figures all run away with the motor’s R_r 10 % high, on every seed (step and sine200 stay at or below 0.5 rad/s; ramp starts and ends at standstill): they show the design with an exact model. A drive needs R_r known to a few per cent where the motor runs slowly, or estimated (the lesson on R_r as an EKF state).',
  },
];
