// The lesson The remedy: the rotor resistance as an EKF state, and when it can be seen. Numbers are placeholders of the measurements table
// (web/teaching/measurements/rr-estimate.csv); see web/teaching/measured.js.
export default {
  id: 'rr-estimate',
  run: 'v=1&preset=rr-mismatch-est&duration=4',
  title: 'The remedy: the rotor resistance as an EKF state, and when it can be seen',
  tab: 'walkthrough',
  plot: 'ekf-plot6', // R̂_r with its ±2σ band against the motor’s
  look: 'The 10 % rotor-resistance mismatch again, over 4 s, this time with R_r as an EKF state (and the RK4 predictor with a small Q). Section 2 of the walkthrough plots R̂_r with its ±2σ band against the motor’s 5.445 Ω. Then set the loads to zero: plant.t0 = model.t0 = 0 and plant.cf = model.cf = 0 in the settings, and run again.',
  question:
    'With the load, where does R̂_r go and what is left of the speed error, against the mismatch lesson’s run over the same window? Without any load or friction, what happens to R̂_r and its band, and why?',
  hint: 'At zero slip the rotor flux turns with the stator field and no current flows in the rotor: what does R_r multiply in the model then?',
  answer:
    'Ranges are over {re.t03.min#draws} noise draws. The R_r state removes the slow transient: at 0.3 s ω − ω_d is {re.t03.min} to {re.t03.max} rad/s instead of {re.nostate03.min} to {re.nostate03.max} rad/s without it, and within 0.05 rad/s of zero as well with the motor’s R_r 10 % below the model’s or the model’s inertia 20 % off either way. At 4 s the speed is {re.end.min} to {re.end.max} rad/s high, against {re.nostate.end.min} to {re.nostate.end.max} rad/s with the same RK4 filter and no R_r state (ekf.rr=0, duration=6). But R̂_r is biased high, whether the motor’s R_r is 10 % above the model’s, equal to it or 10 % below: at 4 s it is {re.hat4.min} to {re.hat4.max} %, {re.exact.hat4.min} to {re.exact.hat4.max} % and {re.low.hat4.min} to {re.low.hat4.max} % of the motor’s R_r. R̂_r is a random walk (its process noise is ekf.q_rr), so its value at the end of a run is one point of a drifting path, not a settled figure: at 8 s (duration=8) it is {re.hat8.min} to {re.hat8.max} %, {re.exact.hat8.min} to {re.exact.hat8.max} % and {re.low.hat8.min} to {re.low.hat8.max} %, at 16 s (duration=16) {re.hat16.min} to {re.hat16.max} %, {re.exact.hat16.min} to {re.exact.hat16.max} % and {re.low.hat16.min} to {re.low.hat16.max} %. Do not read it as a measurement of R_r to better than a few per cent. Nor does its ±2σ band warn of the bias: at 8 s the band is ±{re.band8.min} to ±{re.band8.max} Ω, and the motor’s 5.445 Ω lies inside it on some draws and outside it on others. With no load and no friction the slip is zero, the rotor current is zero, and R_r, which multiplies rotor current terms, leaves little trace in the stator currents: at 4 s the band is ±{re.nl.band.min} to ±{re.nl.band.max} Ω, {re.nl.vs.min} to {re.nl.vs.max} times its width with the load. R_r is well observable only with slip: load, acceleration or a flux transient.',
  holds: [
    // "removes the slow transient": a tenth of the smallest error without the state, and within 0.05 rad/s with the model errors.
    're.t03.max < 0.1 * -re.nostate03.max',
    '-re.t03.min < 0.1 * -re.nostate03.max',
    're.rrlow.t03.max < 0.05',
    're.rrlow.t03.min > -0.05',
    're.jhigh.t03.max < 0.05',
    're.jhigh.t03.min > -0.05',
    're.jlow.t03.max < 0.05',
    're.jlow.t03.min > -0.05',
    're.end.min > 0',
    're.nostate.end.max < 0',
    // biased high on every draw, by over 1 %, for each motor R_r and each length.
    're.hat4.min > 1.01',
    're.exact.hat4.min > 1.01',
    're.low.hat4.min > 1.01',
    're.hat8.min > 1.01',
    're.exact.hat8.min > 1.01',
    're.low.hat8.min > 1.01',
    're.hat16.min > 1.01',
    're.exact.hat16.min > 1.01',
    're.low.hat16.min > 1.01',
    // "better than a few per cent": the bias stays under 5 %.
    're.low.hat16.max < 1.05',
    're.low.hat8.max < 1.05',
    // the band is alike on every draw; the motor's value inside it on the smallest bias, outside on the largest.
    're.band8.max - re.band8.min < 0.005',
    '(re.hat8.min - 1) * 5.445 < re.band8.min',
    '(re.hat8.max - 1) * 5.445 > re.band8.max',
    // "little trace": the band without load is at least twice as wide.
    're.nl.vs.min > 2',
  ],
  givens: [
    '10 % rotor-resistance mismatch',
    'over 4 s',
    'Section 2',
    '±2σ',
    '5.445 Ω',
    'at 0.3 s',
    '0.05 rad/s',
    '10 % below',
    '10 % above',
    '20 % off',
    'At 4 s',
    'at 4 s',
    'at 8 s',
    'at 16 s',
  ],
};
