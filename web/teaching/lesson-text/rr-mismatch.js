// The lesson Rotor-resistance mismatch: a slow transient, then a small bias. Numbers are placeholders of the measurements table
// (web/teaching/measurements/rr-mismatch.csv); see web/teaching/measured.js.
export default {
  id: 'rr-mismatch',
  run: 'v=1&preset=rr-mismatch&duration=6',
  plot: 'speed', // the true speed creeping up to its reference
  title: 'Rotor-resistance mismatch: a slow transient, then a small bias',
  look: 'The motor’s rotor resistance is 10 % above what the EKF and controller assume. This run holds 50 rad/s for 6 s (the preset itself stops at 0.3 s). The speed estimate reaches the reference within milliseconds, while the true speed starts well below it and creeps up over seconds. The figures strip gives the final speed error and says whether it had settled by the end of the run.',
  question:
    'How far below 50 rad/s is the true speed at 0.3 s, at 1 s, and at the end of the 6 s run, and how much of that does the noise draw decide? What makes the recovery slow, and why does the error end on the other side of zero?',
  hint: 'Read ω − ω_d off the error plot with the cursor at 0.3 s and 1 s, then change the noise seed (settings, Noise and seed) and read it again. Open the preset itself (rr-mismatch): its strip says its final value is still changing. For the sign, run the same 6 s with the exact model (plant.rr = 4.95), then both again with the RK4 predictor (ekf = rk4).',
  answer:
    'Ranges are over {rm.t03.min#draws} noise draws. The 10 % error in R_r leaves a slow start-up transient, then a small bias: the true speed ends {rm.end.min} to {rm.end.max} rad/s high, and a run of more than three times the length (duration=20) ends at {rm.long.min} to {rm.long.max} rad/s, between {rm.long.ratio.min} and {rm.long.ratio.max} times the 6 s value, draw by draw: the bias has settled. It ends high as well with the motor’s R_r 10 % below the model’s (plant.rr=4.455: {rm.rrlow.min} to {rm.rrlow.max} rad/s) and with the model’s inertia 20 % off either way ({rm.jhigh.min} to {rm.jlow.max} rad/s), and there too the runs of duration=20 end within a few per cent of the 6 s values. How deep the transient is depends on the noise draw: ω − ω_d is {rm.t03.min} to {rm.t03.max} rad/s at 0.3 s and {rm.t1.min} to {rm.t1.max} rad/s at 1 s. From 20 ms on the estimate stays within {rm.z1} rad/s of the reference (within {rm.z1at03} rad/s around 0.3 s), so the controller is content: the error is the estimate’s. The transient comes from the start-up: from a correct initial estimate (init_err=0) the speed is already {rm.init0.min} to {rm.init0.max} rad/s high at 0.3 s. The model’s wrong R_r is why the filter removes the start-up error so slowly, along a direction the currents barely reveal (its mean NIS from 0.1 s to 1 s is only {rm.nis.min} to {rm.nis.max}): with the exact model (plant.rr = 4.95) ω − ω_d at 0.3 s is already {rm.exact03.min} to {rm.exact03.max} rad/s. The bias’s sign is the Euler predictor’s: with the exact model the Euler EKF alone ends {rm.exact.min} to {rm.exact.max} rad/s high, while with the RK4 predictor the speed ends {rm.rk4exact.min} to {rm.rk4exact.max} rad/s high with the exact model and {rm.rk4.min} to {rm.rk4.max} rad/s with the mismatch: the mismatch alone pulls the speed low, by less than the Euler predictor pushes it high. That pull follows the slip: a larger R_r needs more slip for the same torque, and the filter, assuming the smaller one, puts its speed estimate too high, so the true speed ends low; with the motor’s R_r 10 % below the model’s the RK4 run ends {rm.rk4low.min} to {rm.rk4low.max} rad/s high.',
  holds: [
    // "starts well below it": more than 3 rad/s low at 50 ms on every draw.
    'rm.start < -3',
    'rm.preset.settled == 0',
    // "ends high" and settled: the strip calls every 6 s run settled, and 20 s runs end within 5 % of it, seed by seed.
    'rm.end.min > 0',
    'rm.end.settled == 30',
    'rm.long.ratio.min > 0.95',
    'rm.long.ratio.max < 1.05',
    'rm.rrlow.min > 0',
    'rm.rrlow.ratio.min > 0.95',
    'rm.rrlow.ratio.max < 1.05',
    'rm.jhigh.min > 0',
    'rm.jhigh.min < rm.jlow.min',
    'rm.jlow.max > rm.jhigh.max',
    'rm.jhigh.ratio.min > 0.95',
    'rm.jhigh.ratio.max < 1.05',
    'rm.jlow.ratio.min > 0.95',
    'rm.jlow.ratio.max < 1.05',
    // "the error is the estimate's": the estimate's distance from the reference is under a fifth of the speed error at 0.3 s.
    'rm.z1at03 < 0.1 * -rm.t03.max',
    'rm.t03.max < 0',
    'rm.t1.max < 0',
    // cause: without the start-up error, or without the mismatch, the speed is far closer at 0.3 s.
    'rm.init0.max < 0.1 * -rm.t03.max',
    '-rm.exact03.min < 0.5 * -rm.t03.max',
    // the sign: Euler high with the exact model, RK4 near zero without the mismatch, low with it, high with R_r low.
    'rm.exact.min > rm.end.max',
    'rm.rk4exact.max < 0.1 * rm.exact.min',
    'rm.rk4.max < -10 * rm.rk4exact.max',
    // "by less than the Euler predictor pushes it high".
    'rm.exact.min > -rm.rk4.min',
    'rm.rk4low.min > 10 * rm.rk4exact.max',
  ],
  givens: [
    '10 % above',
    '50 rad/s',
    '6 s',
    '0.3 s',
    'The 10 % error',
    '10 % below',
    '20 % off',
    '20 ms',
    '0.1 s',
    '1 s',
  ],
};
