// The lesson Your own motor. Its texts are messages of web/locales/LANG/lessons.ftl, whose
// numbers are variables of the measurements table (web/teaching/measurements/own-motor.csv).
export default {
  id: 'own-motor',
  run: 'v=1&preset=step&motor=2.2kw',
  plot: 'voltage', // the voltages against their limit
  holds: [
    // "most of the run at the voltage limit", "many times its rating".
    'om.p.sat.min > 0.5',
    'om.p.ipk.min > 5 * om.rated',
    'om.p.nis.min > 100',
    // Each fix alone removes the saturation on every draw.
    'om.rk4.sat.n == 0',
    'om.g.sat.n == 0',
    // "neither alone brings the NIS into its band": outside on more draws than a consistent filter.
    'om.rk4.nlo + om.rk4.nhi > 4',
    'om.g.nlo + om.g.nhi > 4',
    // The derived design: no saturation, within the rating, the NIS in its band but on a few draws.
    'om.d.sat.n == 0',
    'om.d.ipk.max <= om.rated',
    'om.rk4.ipk.max <= om.rated',
    'om.d.nlo + om.d.nhi <= 4',
  ],
  givens: ['2.2 kW', '1200/s', 'ekf.q = 0.001', 'k2 = k3 = k4 = 549.9'],
};
