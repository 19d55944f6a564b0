// The lesson The remedy: the load as an EKF state. Numbers are placeholders of the measurements table
// (web/teaching/measurements/load-estimate.csv); see web/teaching/measured.js.
export default {
  id: 'load-estimate',
  run: 'v=1&preset=load-step-est',
  title: 'The remedy: the load as an EKF state',
  tab: 'walkthrough',
  plot: 'ekf-plot5', // the load estimate with its ±2σ band against the true load
  look: 'The same 2 N m step at 0.15 s, this time with a2 = T_L0/J as a sixth EKF state (a random walk) and the controller using â2 and its rate. In section 2 of the walkthrough, the load-torque plot shows the estimate with its ±2σ band against the true load; compare the speed with the lesson “An unknown load step”.',
  question:
    'How far does the speed dip after the step, and what does the load estimate settle to? Why must the load be a state of the observer rather than a constant the controller is told? Does the remedy hold when the model’s rotor resistance is off?',
  hint: 'On the Trajectories tab, drag across 0.14–0.2 s on the plot “Speed tracking error ω − ω_d”: it zooms in, its y-axis fits the dip, and the cursor reads it. Then read the load-torque plot in section 2 after 0.2 s. Think about what the currents can tell the filter about the torque balance a1(x3x4 − x2x5) − a2 − a3x1 = ω̇. Last, set plant.rr = 4.455 (the motor’s R_r 10 % below the model’s) and run again.',
  answer:
    'Ranges are over {le.dip.min#draws} noise draws. With an exact model ω − ω_d dips to {le.dip.min} to {le.dip.max} rad/s after the step and is back within 0.05 rad/s {le.back.min} to {le.back.max} ms after it, while the load estimate, a random walk of the filter, averages {le.load.min} to {le.load.max} N m over the last 0.1 s, and over the last 0.1 s of a 3 s run (duration=3) still {le.load3.min} to {le.load3.max} N m. The remedy holds with the model’s inertia 20 % off either way (a dip to {le.jlow.dip} rad/s at worst, back within {le.jlow.back} ms), but not with the motor’s rotor resistance off, over 3 s: 10 % above the model’s leaves a steady {le.rrhigh.end.min} to {le.rrhigh.end.max} rad/s (a run four times as long, duration=12, ends at {le.rrhigh.ratio.min} to {le.rrhigh.ratio.max} times the 3 s value, draw by draw), 3 % below (plant.rr=4.8015) leaves {le.rr3.rms.min} to {le.rr3.rms.max} rad/s RMS over the last second, and 10 % below loses the speed ({le.rrlow.rms.min} to {le.rrlow.rms.max} rad/s RMS, mean NIS {le.rrlow.nis.min} to {le.rrlow.nis.max}). The dip shows on the zoomed error plot. The load estimate’s ±2σ band is ±{le.band.max} N m at the end of the preset’s run, and its average, {le.load.min} to {le.load.max} N m, is T0 = 0.5 plus the 2 N m step to within a hundredth. A constant a2 cannot follow an unknown change; as a state with process noise, the innovation drives â2 to whatever torque balance makes the predicted currents match the measured ones, and the controller feeds â2 (and dâ2/dt, its injection) forward. The preset uses the RK4 predictor and a small Q: with the paper’s Euler predictor and Q (ekf=euler&ekf.q=0.001) the extra state, free to move fast, takes up the predictor’s own error, and ω − ω_d ends at {le.euler.min} to {le.euler.max} rad/s at 0.3 s. Either change alone removes most of that: the RK4 predictor with the paper’s Q (ekf.q=0.001) ends at {le.rk4q.min} to {le.rk4q.max} rad/s, the Euler predictor with the preset’s small Q (ekf=euler) at {le.eulersmallq.min} to {le.eulersmallq.max} rad/s. An extra state absorbs whatever the model lacks, right or wrong: give the filter the rotor resistance instead of the load (load-step with ekf.rr=1, over 3 s) and R̂_r takes up the load, at {le.rrstate.hat.min} to {le.rrstate.hat.max} Ω after 3 s against the motor’s 4.95 Ω, while ω − ω_d ends at {le.rrstate.end.min} to {le.rrstate.end.max} rad/s with a mean NIS of {le.rrstate.nis.min} to {le.rrstate.nis.max}.',
  holds: [
    // one value written for the range.
    'le.load.max - le.load.min < 0.005',
    'le.load3.max - le.load3.min < 0.005',
    'le.band.max - le.band.min < 0.005',
    // "T0 + 2 N m to within a hundredth", at the end of the preset's run and of a 3 s run.
    'le.load.min > 2.49',
    'le.load.max < 2.51',
    'le.load3.min > 2.49',
    'le.load3.max < 2.51',
    // the inertia worst cases written are the worse of the two signs.
    'le.jlow.dip <= le.jhigh.dip',
    'le.jlow.back >= le.jhigh.back',
    // "holds": within 1.1 times the exact model's worst dip and 10 ms.
    'le.jlow.dip > 1.1 * le.dip.min',
    'le.jlow.back < 0.01',
    // "steady": little variation over the last second, and a 12 s run ends within 5 % of the 3 s value on each draw.
    'le.rrhigh.sd < 0.01 * -le.rrhigh.end.max',
    'le.rrhigh.ratio.min > 0.95',
    'le.rrhigh.ratio.max < 1.05',
    // the Euler predictor with the paper's Q: far worse than either change alone.
    'le.euler.max < -10 * le.eulersmallq.max',
    'le.rk4q.max < 0.1 * -le.euler.max',
    '-le.rk4q.min < 0.1 * -le.euler.max',
    'le.eulersmallq.min > 0',
    // R̂_r "takes up the load": well above the motor's 4.95 Ω on every draw.
    'le.rrstate.hat.min > 1.05 * 4.95',
  ],
  givens: [
    '2 N m',
    '0.15 s',
    '±2σ',
    'section 2',
    '0.14–0.2 s',
    'after 0.2 s',
    '10 % below',
    '0.05 rad/s',
    '0.1 s',
    'at 0.3 s',
    '3 s',
    '20 % off',
    '10 % above',
    '3 % below',
    'T0 = 0.5',
    '4.95 Ω',
  ],
};
