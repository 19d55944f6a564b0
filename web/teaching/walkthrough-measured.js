// The design walkthrough's measured statements (its English messages,
// web/locales/en/walkthrough.ftl): the conditions its words state over its measurements table
// (web/teaching/measurements/walkthrough.csv) and the phrases with digits that are settings or
// constants, not measurements. tests/measurements.test.mjs checks both.

// What the words state about the runs, as conditions over the table.
export const WALKTHROUGH_HOLDS = [
  // "The Euler predictor cannot follow 200 Hz currents": its NIS far above RK4's on every draw.
  'wt.ekf.euler.nis > 10 * wt.ekf.rk4.nis',
  // "a rotor-resistance state under an unknown load takes the load for a resistance": with the
  // load step R̂_r ends more than 5 % above the motor's 4.95 Ω on every draw, without it below.
  'wt.ekf.rrload.min > 1.05 * 4.95',
  'wt.ekf.rrnoload.max < 4.95',
  // "runs away or fails ...: the flux runs off on N and the controller fails before the end on M":
  // wt.rrhigh.off counts the draws whose flux ends the 0.1 s above 5 × its 0.707 Wb target,
  // wt.rrhigh.fail those that stop before 90 ms; together they are the ran_away count.
  'wt.rrhigh.off + wt.rrhigh.fail == wt.rrhigh.runaway',
  'wt.rrhigh.flux.min > 5 * 0.707',
  'wt.rrhigh1s.flux.min > 2 * wt.rrhigh.flux.max',
  // "the noise enters z3 through the innovations": without it z3 is less than half as large.
  'wt.z3.min > 2 * wt.z3.quiet',
  // "whose estimate is the motor's flux": the perfect observer leaves z3 next to nothing.
  'wt.z3.perfect.max < 0.01 * wt.z3.quiet',
  // "far beyond the limit" (400 V).
  'wt.cmd.step.min > 10 * 400',
  'wt.cmd.rr.min > 10 * 400',
  // "the voltage limit holds the start-up" with an exact model: no runaway with it, most without
  // it; with R_r 10 % high it does not.
  'wt.limit.runaway == 0',
  'wt.limit.rrhigh.runaway > 0',
  'wt.nolimit.runaway > 0',
  // "tracks ... on every draw with an exact model".
  'wt.exact.runaway == 0',
  // "fails even so": its RMS error over a hundred times the exact model's on every draw.
  'wt.exact.rrhigh.rms > 100 * wt.exact.rms.max',
  // "V stops at a floor" (within 2 % of its end value from 15 ms on) "while the bound falls on,
  // so that V ends far above it": the bound at the end of decay's 20 ms is V(0)·e^(−2400·0.02).
  'wt.decay.v15 < 1.02 * wt.decay.floor',
  'wt.decay.floor > 1e6 * 1.43e-21 * wt.decay.v0',
  // "of the order of Ts in the z_i": halving Ts quarters V, a sum of squares of the z_i.
  'wt.decay.halfts > 0.2',
  'wt.decay.halfts < 0.3',
  // "far above that floor" for an R_r error; "does not" for an inertia error: within a factor 2.
  'wt.decay.rrhigh > 1000',
  'wt.decay.rrlow > 1000',
  'wt.decay.jhigh > 0.5',
  'wt.decay.jhigh < 2',
  'wt.decay.jlow > 0.5',
  'wt.decay.jlow < 2',
];

// Phrases of the walkthrough with digits that are settings or constants, not measurements.
export const WALKTHROUGH_GIVENS = [
  'a1 = 3n_pM/(2JL_r)',
  'contains 1/J',
  'σ = 1 − M²/(L_sL_r)',
  'their ±2σ band about 95 % of the time',
  'averaging 2',
  '200 Hz currents',
  'Section 3.1 names',
  'their ±2σ bands from P',
  'u_{k|k−1}',
  'u_{k−1}',
  'x̂_{k|k−1}',
  'the short form (I − K_kC)P_{k|k−1}',
  'x̃1 = x̃4 = x̃5 = 0',
  'in rows 2 to 5. Row 1 only nearly',
  '(1/s² in SI)',
  'as step 4 sets h4 (53)',
  'step 4’s d̃4 plot',
  'well below about 2/Ts',
  'the flux’s own decay −2a8·(x̂4² + x̂5²) included',
  'where in step 1 the motor’s damping',
  'a6·x̂1·(x̂4·x̂5 − x̂5·x̂4) = 0',
  'with λ4 = 2·min(k3, k4)',
  'as section 8 does for V',
  'Assumption 4.2 (22)',
  'the rate h2²/(4ε2) that v2s2 adds',
  'In the derivative of 2a10·(x2·x̂4 + x3·x̂5)',
  'bounded under Assumption 4.2',
  'in step 2 (ż2 holds',
  'in step 4 (ż4 holds',
  'Steps 1 and 3',
  'Step 1',
  'Steps 1 and 2',
  'steps 3 and 4',
  'step 2 cancels',
  'Step 2',
  '(section 3)',
  'h2²z2/(4ε2)',
  'R_r 10 % above',
  'the preset’s 0.1 s',
  'after 1 s',
  'Step 3',
  'ż3 = 2x̂4·x̂̇4 + 2x̂5·x̂̇5',
  'the virtual control 2a10(x2·x̂4 + x3·x̂5)',
  'step 4 cancels',
  '|φ| = 0.707 Wb',
  '“ϕ_d = 0.5”',
  'read literally is 0.5 Wb (0.25 Wb²)',
  'initial flux [0.5, 0.5]',
  'from 15 ms on',
  'Step 4',
  'v4 = 2a10·b(x̂4·u1 + x̂5·u2)',
  'the first line of step 3',
  'with L̇ = 0',
  '2(l41·x̂4 + l51·x̂5) and 2(l42·x̂4 + l52·x̂5)',
  'a 400 V limit',
  '±400 V',
  '2a10(l21·x̃2·x̂4 + …) for 2a10(x̂4·si2 + x̂5·si3)',
  'In its first 5 ms',
  'Assumption 4.2',
  'h2²z2²/(4ε2)',
  '= 2·min(k_i)·V',
  'from 0 to t',
  'the EKF’s 10 % initial error',
  'seeds 1 to',
  'inertia 20 % above and below',
  'd̃2 = d̃4 = 0',
  'assumes d̃ = 0',
  'the 20 kHz sampling',
];
