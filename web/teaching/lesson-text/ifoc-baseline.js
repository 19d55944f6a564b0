// The lesson The classical baseline, like for like: field-oriented control on the same ramp and
// current. Its texts are messages of web/locales/LANG/lessons.ftl, whose numbers are variables of
// the measurements table (web/teaching/measurements/ifoc-baseline.csv).
export default {
  id: 'ifoc-baseline',
  run: 'v=1&preset=ifoc-step&ref=ramp&ramp.level=40&ramp.slope=200&ramp.hold=5&ifoc.i_max=3.7&duration=1.5',
  plot: 'speed', // the speed falling behind the ramp
  holds: [
    'ib.bs.ra == 0',
    'ib.if.ra == 0',
    // "far closer": backstepping's largest lag is under a tenth of the IFOC's.
    '10 * ib.bs.tp < ib.if.tp',
    // "passes 4 A on … draws, up to … in the start-up transient".
    'ib.bs.all.over > 0',
    'ib.bs.start.ipk == ib.bs.all.ipk',
    // The IFOC within the 4 A rating over the whole run, exact model and R_r ±10 %.
    'ib.if.ipk < 4',
    'ib.if.p10.ipk < 4',
    'ib.if.m10.ipk < 4',
    // One recovery time for every draw (shown to two digits).
    'ib.if.rec.max - ib.if.rec.min < 0.005',
    // "the runs that hold … from init_err = 0": all of them, so the peaks are theirs.
    'ib.bs.p5.init.ra == 0',
    // "at most … either way".
    'ib.if.p10.ipk <= ib.if.m10.ipk',
    // The load state is the remedy; the RK4 predictor alone is not.
    'ib.bl.load.fin.min > 0.2 * ib.bl.fin.min',
    'ib.bl.est.fin < 0.1',
    'ib.bl.rk4.fin.max < 0.9 * ib.bl.fin.max',
  ],
  givens: [
    'α_c = 2π·1 kHz',
    'poles at −2π·50 Hz',
    'speed loop at 10 Hz',
    'Ki = Kp·α_ω/4',
    'ramp at 200 rad/s² to 40 rad/s',
    'limited to 3.7 A so that |i_s| stays within the 4 A rating',
    'against the 4 A rating',
    'ramp ends (at 0.25 s)',
    'within 2 % of 40 rad/s',
    'R_r 10 % above the model’s (plant.rr = 5.445)',
    'load.time = 1 and duration = 2',
    '5-state design',
    'seeds 1 to',
    'over the 4 A rating on',
    'passes 4 A on',
    'within 2 % (0.8 rad/s) of 40 rad/s',
    'at 4 % above',
    'at 5 % above',
    'at 7 % above',
    'R_r 10 % below',
    'R_r 10 % high or low',
    'A 2 N m step at 1 s',
    'back within 0.5 rad/s',
  ],
};
