// The lesson Where sensorless control cannot see: low speed. Numbers are placeholders of the measurements table
// (web/teaching/measurements/low-speed.csv); see web/teaching/measured.js.
export default {
  id: 'low-speed',
  run: 'v=1&preset=rr-mismatch&ref.value=1&ekf=rk4&init_err=0&duration=3',
  plot: 'speed', // where the speed estimate goes
  title: 'Where sensorless control cannot see: low speed',
  look: 'This run holds 1 rad/s for 3 s against the preset’s constant load, with the motor’s R_r 10 % above the model’s, the RK4 predictor and a correct initial estimate (ekf = rk4, init_err = 0). The paper’s own step and sine200 ask for at most 0.5 rad/s. Watch ω̂ on the speed plot and the voltage plot; the walkthrough’s EKF section plots the speed variance and the NIS.',
  question:
    'Where does the speed estimate go, what does the controller do with it, and what do the mean NIS and the peak current say? Then run it with the exact model (plant.rr = 4.95), with the motor’s R_r 10 % below the model’s (plant.rr = 4.455), and with the mismatch at ref.value = 10.',
  hint: 'Read the message above the plots, then “share of samples at the voltage limit”, “mean NIS” and “peak stator current” (under “All figures” on a small screen); the strip’s window starts {ls.window.min} to {ls.window.max} s into the run. Drag across the first 40 ms of the plots to see what goes first.',
  answer:
    'Ranges are over {ls.ra#draws} noise draws (seeds 1 to {ls.ra#draws}), in 3 s runs with RK4 and init_err = 0. With the motor’s R_r 10 % above the model’s this loop runs away on {ls.p10.w0.ra} of {ls.p10.w0.ra#draws} draws at each of 0, 1, 3, 5 and 6.5 rad/s and on {ls.p10.w7.ra} at each of 7, 10 and 15 rad/s; with R_r 10 % below the model’s on {ls.m10.w0.ra} at each of 0, 1, 5 and 15 rad/s, ending {ls.m10.w0.min} to {ls.m10.w15.max} rad/s high. At low speed the sign of the error decides. The page reports this run as ran away on {ls.ra} of {ls.ra#draws} draws. The flux goes first: at 15 ms the flux estimate less the true flux is {ls.flux15.min} to {ls.flux15.max} Wb while ω̂ has stayed between {ls.what15.min} and {ls.what15.max} rad/s; the controller, which regulates the estimate, drives the voltage to the limit and keeps it there from {ls.limit.min} to {ls.limit.max} ms on, and ω̂ ends at least {ls.whatend} rad/s from zero while the true speed reaches up to {ls.swing} rad/s. In the strip’s window the share of samples at the voltage limit is {ls.sat.pc} % even on the draw with the fewest, the peak current is {ls.ipk.min} to {ls.ipk.max} A (the rating is 4 A) and the mean NIS is {ls.nis.min} to {ls.nis.max}: the filter’s model no longer fits at all. The wrong R_r is the cause: with the exact model the same loop, holding 1 rad/s, runs away on {ls.exact.ra} of {ls.exact.ra#draws} draws and ends within {ls.exact.err} mrad/s. The load is not: without it (plant.t0 = model.t0 = 0, plant.cf = model.cf = 0) the run still runs away on {ls.noload.ra} of {ls.noload.ra#draws} draws, and with the exact model on {ls.noload.exact.ra}. The speed below which the loop fails rises with the error: with R_r 5 % high it runs away at 1 rad/s on {ls.p5.w1.ra} of {ls.p5.w1.ra#draws} draws and on {ls.p5.w1_5.ra} at each of 1.5, 2, 5 and 15 rad/s; 20 % high on {ls.p20.w10.ra} at each of 10 and 12.5 rad/s and on {ls.p20.w15.ra} at 15. These runs do not show why only an R_r above the model’s fails: the usual argument, that the speed and the flux reach the stator currents through a back-EMF that shrinks with the stator frequency, says why low speed is hard, not why one sign of error fails and the other does not. The paper’s own figures are in this region: with the motor’s R_r 10 % above the model’s, step, sine200 and ramp (which starts from standstill) run away on {ls.paper.step.ra}, {ls.paper.sine200.ra} and {ls.paper.ramp.ra} of {ls.paper.step.ra#draws} draws; the lesson “How exact must the model be?” maps the errors around step. The simulated motor does not saturate magnetically, so in this run its flux grows past {ls.flux} Wb; a real one would saturate first.',
  holds: [
    'ls.ra > 0',
    'ls.sat == 1',
    // "runs away on … at each of …": each speed as the first named.
    'ls.p10.w1.ra == ls.p10.w0.ra',
    'ls.p10.w3.ra == ls.p10.w0.ra',
    'ls.p10.w5.ra == ls.p10.w0.ra',
    'ls.p10.w6_5.ra == ls.p10.w0.ra',
    'ls.p10.w10.ra == ls.p10.w7.ra',
    'ls.p10.w15.ra == ls.p10.w7.ra',
    // "At low speed the sign of the error decides".
    'ls.p10.w0.ra > ls.m10.w0.ra',
    'ls.p10.w7.ra == 0',
    'ls.m10.w1.ra == ls.m10.w0.ra',
    'ls.m10.w5.ra == ls.m10.w0.ra',
    'ls.m10.w15.ra == ls.m10.w0.ra',
    // R_r 10 % low: the final error of each speed lies in the range stated.
    'ls.m10.w1.min >= ls.m10.w0.min',
    'ls.m10.w5.min >= ls.m10.w0.min',
    'ls.m10.w15.min >= ls.m10.w0.min',
    'ls.m10.w0.max <= ls.m10.w15.max',
    'ls.m10.w1.max <= ls.m10.w15.max',
    'ls.m10.w5.max <= ls.m10.w15.max',
    'ls.m10.w0.min > 0',
    // "The flux goes first": the flux estimate is below the true flux at 15 ms on every draw,
    // while ω̂ has not left 1 rad/s by more than 1 %.
    'ls.flux15.max < 0',
    'ls.what15.min > 0.99',
    'ls.what15.max < 1.01',
    // "the wrong R_r is the cause": the exact model removes the failure, with or without the load.
    'ls.exact.ra < ls.ra',
    'ls.noload.exact.ra < ls.noload.ra',
    // "The load is not": removing the load leaves the failure.
    'ls.noload.ra > 0',
    // "rises with the error".
    'ls.p5.w1.ra > 0',
    'ls.p5.w2.ra == ls.p5.w1_5.ra',
    'ls.p5.w5.ra == ls.p5.w1_5.ra',
    'ls.p5.w15.ra == ls.p5.w1_5.ra',
    'ls.p20.w12_5.ra == ls.p20.w10.ra',
    'ls.p20.w10.ra > ls.p20.w15.ra',
  ],
  givens: [
    'holds 1 rad/s for 3 s',
    'R_r 10 % above the model’s',
    'ask for at most 0.5 rad/s',
    'R_r 10 % below the model’s',
    'first 40 ms of the plots',
    'seeds 1 to',
    'in 3 s runs',
    'at each of 0, 1, 3, 5 and 6.5 rad/s',
    'at each of 7, 10 and 15 rad/s',
    'at each of 0, 1, 5 and 15 rad/s',
    'at 15 ms',
    'holding 1 rad/s',
    'the rating is 4 A',
    'R_r 5 % high',
    'at 1 rad/s on',
    'at each of 1.5, 2, 5 and 15 rad/s',
    '20 % high on',
    'at each of 10 and 12.5 rad/s',
    'at 15.',
  ],
};
