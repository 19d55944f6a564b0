// The lesson An unknown load step. Numbers are placeholders of the measurements table
// (web/teaching/measurements/load-step.csv); see web/teaching/measured.js.
export default {
  id: 'load-step',
  run: 'v=1&preset=load-step&duration=3',
  plot: 'speed', // the true speed and its estimate after the load step
  title: 'An unknown load step',
  look: 'At 0.15 s a 2 N m load torque appears that neither the EKF nor the controller knows about. This run lasts 3 s (the preset stops at 0.3 s, in the middle of the fall). Watch the true speed and its estimate after 0.15 s, and read the final errors in the figures strip.',
  question:
    'Where does the true speed end, where does the estimate end, and how much of the loss is the controller’s and how much the observer’s?',
  hint: 'Read “final speed error ω − ω_d” and “final speed-estimate error ω − ω̂”. Then run it with a perfect observer (perfect = 1 in the Observer settings): the controller then sees the true state.',
  answer:
    'Ranges are over {lst.end.min#draws} noise draws. The true speed ends {lst.end.min} to {lst.end.max} rad/s off the reference (ω − ω_d), while from 0.2 s on the estimate stays within {lst.z1} rad/s of it: the loss is the observer’s. With a perfect observer (perfect = 1) the controller alone ends at {lst.perfect.mean} rad/s. That holds with the model off as well: with the motor’s R_r 10 % off or the model’s inertia 20 % off, either way, ω − ω_d ends at {lst.jlow.min} to {lst.jhigh.max} rad/s, and with a perfect observer at {lst.perfect.jlow} rad/s at worst. The true speed falls for about a second (ω − ω_d is {lst.t03.min} to {lst.t03.max} rad/s at 0.3 s, {lst.t05.min} to {lst.t05.max} at 0.5 s, {lst.t1.min} to {lst.t1.max} at 1 s) and then settles: a run four times as long (duration=12) ends at {lst.long.ratio.min} to {lst.long.ratio.max} times the 3 s value, draw by draw. The estimate ends on the reference (ω − ω̂ = {lst.est.min} to {lst.est.max} rad/s) and the filter is far from consistent (mean NIS {lst.nis.min} to {lst.nis.max}). With a perfect observer the error is ΔT/J·(1/k1 + 1/k2), the droop of a design without integral action. The rest is the 5-state EKF’s: its model holds the load at a2 = T0/J, so it explains the load’s effect on the currents with a wrong speed and flux (its flux error ends at {lst.flux.max} Wb); with the load as a sixth state of the filter (the next lesson’s preset, load-step-est, over the same 3 s) ω − ω_d ends at only {lst.loadstate.min} to {lst.loadstate.max} rad/s. Two remedies: make the load a state of the filter (next lesson), or let the speed estimate move faster than the model says: ekf.q_speed adds process noise to the speed state alone. At ekf.q_speed=1e7 the RMS of ω − ω_d over the last second of the run is {lst.q1e7.rms.min} to {lst.q1e7.rms.max} rad/s. Less or more process noise leaves more: {lst.q1e6.rms.min} to {lst.q1e6.rms.max} rad/s at ekf.q_speed=1e6, {lst.q1e8.rms.min} to {lst.q1e8.rms.max} rad/s at ekf.q_speed=1e8, and either way it is a bias, not noise: the speed stays low (its mean over that second is at most {lst.q1e6.mean.max} and {lst.q1e8.mean.max} rad/s) and at both the mean carries at least {lst.q1e8.share.min} % of the mean square. The error is smallest near ekf.q_speed=1e7: at ekf.q_speed=3e6 it is at least {lst.q3e6.rms.min} rad/s, at ekf.q_speed=3e7 at least {lst.q3e7.rms.min} rad/s. That remedy holds with the model’s inertia 20 % off either way (at most {lst.q7.jlow.max} rad/s RMS) but not with the motor’s R_r 10 % off: ekf.q_speed=1e7 then leaves {lst.q7.rrhigh.min} to {lst.q7.rrhigh.max} rad/s RMS with R_r above the model’s, a bias (the mean carries at least {lst.q7.rrhigh.share} % of the mean square), and {lst.q7.rrlow.min} to {lst.q7.rrlow.max} rad/s with it below, most of it not a bias (the mean carries at most {lst.q7.rrlow.share} %).',
  holds: [
    // "the loss is the observer's": the estimate sits on the reference while the speed is far off.
    'lst.z1 < 0.01 * -lst.end.max',
    'lst.est.min > 1.01 * lst.end.min',
    // one value written for the range: the ends differ by less than the last digit shown.
    'lst.end.min - lst.end.max > -0.05',
    'lst.est.min - lst.est.max > -0.05',
    // the perfect observer's run does not depend on the draw.
    'lst.perfect.min == lst.perfect.max',
    'lst.perfect.mean == lst.perfect.max',
    'lst.flux.min - lst.flux.max > -0.005',
    'lst.est.max < 0.99 * lst.end.max',
    // the model-error range written as one range: its ends are the extremes of all four.
    'lst.jlow.min <= lst.rrhigh.min',
    'lst.jlow.min <= lst.rrlow.min',
    'lst.jlow.min <= lst.jhigh.min',
    'lst.jhigh.max >= lst.rrhigh.max',
    'lst.jhigh.max >= lst.rrlow.max',
    'lst.jhigh.max >= lst.jlow.max',
    'lst.perfect.jlow <= lst.perfect.rrhigh',
    'lst.perfect.jlow <= lst.perfect.rrlow',
    'lst.perfect.jlow <= lst.perfect.jhigh',
    // "falls for about a second": within 3 % of its end value at 1 s.
    'lst.t1.min > 1.03 * lst.end.min',
    // settles: 12 s runs end within 0.1 % of the 3 s ones, seed by seed.
    'lst.long.ratio.min > 0.999',
    'lst.long.ratio.max < 1.001',
    // ΔT/J·(1/k1 + 1/k2) = (2/0.02)·(2/1200) = 0.16667 rad/s.
    'lst.perfect.min > -0.16667 - 0.0005',
    'lst.perfect.max < -0.16667 + 0.0005',
    // cause: with the load as a filter state the loss goes.
    'lst.loadstate.min > -0.01 * -lst.end.max',
    'lst.loadstate.max < 0.01 * -lst.end.max',
    // "a bias, not noise" at 1e6 and 1e8; "low".
    'lst.q1e6.share.min >= lst.q1e8.share.min',
    'lst.q1e8.share.min > 0.9',
    'lst.q1e6.mean.max < 0',
    'lst.q1e8.mean.max < 0',
    // "smallest near 1e7".
    'lst.q1e7.rms.max < lst.q3e6.rms.min',
    'lst.q1e7.rms.max < lst.q3e7.rms.min',
    'lst.q1e7.rms.max < lst.q1e6.rms.min',
    'lst.q1e7.rms.max < lst.q1e8.rms.min',
    // "holds" with the inertia off: within 1.5 times the exact model's worst draw.
    'lst.q7.jlow.max < 1.5 * lst.q1e7.rms.max',
    'lst.q7.jhigh.max < 1.5 * lst.q1e7.rms.max',
    'lst.q7.rrhigh.min > 3 * lst.q1e7.rms.max',
    'lst.q7.rrhigh.share > 0.9',
    'lst.q7.rrlow.share < 0.5',
  ],
  givens: [
    '0.15 s',
    '0.3 s',
    '0.2 s',
    '0.5 s',
    '2 N m',
    '3 s',
    '1 s',
    '10 % off',
    '20 % off',
    '5-state',
    'ΔT/J·(1/k1 + 1/k2)',
  ],
};
