// The lesson Gains past what the observer supports. Numbers are placeholders of the measurements table
// (web/teaching/measurements/high-gain.csv); see web/teaching/measured.js.
export default {
  id: 'high-gain',
  run: 'v=1&preset=high-gain',
  title: 'Gains past what the observer supports',
  tab: 'walkthrough',
  plot: 'step4-plot', // the voltage before and after the limit
  look: 'All four gains are 3000/s, 2.5× the paper’s. The voltage limit is hit almost all the time. The knobs k1–k4 in the Step sections and the EKF predictor and noise in the EKF section re-run the scenario when you change them; the figures strip follows, over the preset’s 0.1 s.',
  question:
    'What share of samples is at the voltage limit at 3000/s? Then try the RK4 predictor (EKF section) and, separately, noise 0 (settings, Noise and seed): which one removes the saturation, and what does that say limits the gains? Does that hold with the model off?',
  hint: 'With perfect = 1 (Observer settings) even 20,000/s settles on {hg.k20k.reached} of {hg.k20k.reached#draws} draws, with a sample at the limit on {hg.k20k.sat.n} of them, at 20 kHz, so sampling is not the limit. Change one thing at a time and read “share of samples at the voltage limit”; then set model.j = 0.024 or 0.016, or plant.rr = 4.455 or 5.445.',
  answer:
    'Ranges are over {hg.sat.min#draws} noise draws. The Euler predictor’s model error, amplified by the gains, keeps the voltage at the limit, not the measurement noise: the RK4 predictor removes the saturation, noise 0 does not. At 3000/s {hg.sat.min} to {hg.sat.max} % of the strip’s samples are at the limit, and with noise 0 still {hg.noise0.sat} %; with the RK4 predictor {hg.rk4.sat.n} of {hg.rk4.sat.n#draws} draws have any sample there. The Euler filter’s mean NIS is {hg.nis.min} to {hg.nis.max}, far outside its band, whose lower edge is {hg.band.low}–{hg.band.low.max} and upper edge {hg.band.high.min}–{hg.band.high} over the draws: its model of its own errors is wrong, and at the paper’s 1200/s the same filter leaves a sample at the limit in the strip on {hg.g1200.sat.n} of {hg.g1200.sat.n#draws} draws. This holds with the model’s inertia 20 % off either way and with the motor’s R_r 10 % below the model’s: the Euler predictor still keeps at least {hg.rrlow.euler.min} % of the samples at the limit and RK4 at most {hg.rrlow.rk4.max} %, with runs running away on {hg.jhigh.euler.away} of {hg.jhigh.euler.away#draws} draws in each of these six cases. With R_r 10 % above, this 0.5 rad/s step is lost on {hg.rrhigh.euler.away} and {hg.rrhigh.rk4.away} of {hg.rrhigh.euler.away#draws} draws with the Euler and the RK4 predictor: the run runs away or the controller fails (see the lesson on low speed). Counted over the whole run, the Euler EKF’s start-up clips the voltage even at the paper’s gains: {hg.g1200.clip.min} to {hg.g1200.clip.max} % of the samples at 1200/s, all in the first 2 ms, before the strip’s window starts, at {hg.g1200.tend.min} to {hg.g1200.tend.max} ms.',
  holds: [
    // "almost all the time".
    'hg.sat.min > 0.99',
    // The Euler predictor removed: the saturation goes. The noise removed: it stays.
    'hg.rk4.sat.max < 0.002',
    'hg.noise0.sat > 0.99',
    'hg.away == 0',
    'hg.rk4.away == 0',
    'hg.nis.min > 10 * hg.band.high',
    // The gains removed.
    'hg.g1200.sat.max < 0.002',
    // With each model error: the least Euler share and the largest RK4 share are the quoted ones.
    'hg.jhigh.euler.min >= hg.rrlow.euler.min',
    'hg.jlow.euler.min >= hg.rrlow.euler.min',
    'hg.rrlow.euler.min > 0.98',
    'hg.jlow.rk4.max <= hg.rrlow.rk4.max',
    'hg.jhigh.rk4.max <= hg.rrlow.rk4.max',
    // "in each of these six cases" as often as the first.
    'hg.jlow.euler.away == hg.jhigh.euler.away',
    'hg.rrlow.euler.away == hg.jhigh.euler.away',
    'hg.jhigh.rk4.away == hg.jhigh.euler.away',
    'hg.jlow.rk4.away == hg.jhigh.euler.away',
    'hg.rrlow.rk4.away == hg.jhigh.euler.away',
    // "all in the first 2 ms, before the strip's window starts".
    'hg.g1200.late == 0',
    'hg.g1200.tend.min > 0.002',
    // 20,000/s with a perfect observer: "settles".
    'hg.k20k.away == 0',
    'hg.k20k.reached > 0',
  ],
  givens: [
    '3000/s',
    '2.5× the paper’s',
    'k1–k4',
    'preset’s 0.1 s',
    '20,000/s',
    'at 20 kHz',
    'paper’s 1200/s',
    'at 1200/s',
    '20 % off',
    '10 % below',
    '10 % above',
    '0.5 rad/s step',
    'first 2 ms',
    'noise 0',
    'or 0.016',
    'or 5.445',
  ],
};
