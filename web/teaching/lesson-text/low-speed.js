// The lesson Where sensorless control cannot see: low speed. Its texts are messages of
// web/locales/LANG/lessons.ftl, whose numbers are variables of the measurements table
// (web/teaching/measurements/low-speed.csv).
export default {
  id: 'low-speed',
  run: 'v=1&preset=rr-mismatch&ref.value=1&ekf=rk4&init_err=0&duration=3',
  plot: 'speed', // where the speed estimate goes
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
