// The lesson Does 200 Hz survive a real drive?. Its texts are messages of
// web/locales/LANG/lessons.ftl, whose numbers are variables of the measurements table
// (web/teaching/measurements/real-drive.csv).
export default {
  id: 'real-drive',
  run: 'v=1&preset=sine200-drive&duration=1',
  plot: 'speed-error', // ω − ω_d, whose RMS the question compares
  holds: [
    // "the hexagon and PWM scale it by only": within 1 % on every draw.
    'rd.hexpwm.min > 0.99',
    'rd.hexpwm.max < 1.01',
    // "wins part of it back": the compensated RMS is below the delayed one, above the ideal one.
    'rd.comp.max < rd.delay.min',
    'rd.comp.min > rd.sine.max',
    // "as well as the ideal one": within 2 % on every draw.
    'rd.rk4ratio.min > 0.98',
    'rd.rk4ratio.max < 1.02',
    // "the tracking's own": the strip's peak and the current from 50 ms on agree within 1 %.
    'rd.i50.min >= 0.99 * rd.ipk.min',
    'rd.i50.max <= 1.01 * rd.ipk.max',
    'rd.i50.min > 4',
    'rd.comp.i50.min > 4',
    'rd.comprk4.i50.min > 4',
    'rd.amp26.max < 4',
    'rd.amp28.min > 4',
    'rd.amp26.jhigh.min > 4',
    'rd.amp26.rrlow.min > 4',
    // "only": the still errors change the RMS by at most a fifth of the tracking errors' least change.
    'rd.still.jlow.max - 1 < 0.2 * (rd.jlow.min - 1)',
    'rd.still.jhigh.max - 1 < 0.2 * (rd.jlow.min - 1)',
    '1 - rd.still.jhigh.min < 0.2 * (rd.jlow.min - 1)',
    '1 - rd.still.jlow.min < 0.2 * (rd.jlow.min - 1)',
    // "cost as much": a perfect observer does not lower the RMS with either error.
    'rd.perfect.jhigh.min >= 1',
    'rd.perfect.jlow.min >= 1',
  ],
  givens: [
    'Does 200 Hz survive',
    'hexagon of a 540 V DC link',
    '540/√3 ≈ 311.8 V from its centre to its flats and 360 V at its corners',
    '±400 V box has 566 V corners',
    'PWM at 20 kHz',
    'This run lasts 1 s',
    'stops at 0.25 s',
    '4 A rating',
    'the same 1 s',
    'inertia 20 % off',
    'resistance 10 % off',
    'from 50 ms on',
    'within 4 A',
    'at 0.26 rad/s',
    'at 0.28 rad/s',
    '20 % high',
    '10 % below',
    '10 % above',
    'the 200 Hz tracking',
    'and 0.016',
    'and 4.455',
    'or 0.016',
    'x̂_(k+1|k)',
    'ω_d ≡ 0',
  ],
};
