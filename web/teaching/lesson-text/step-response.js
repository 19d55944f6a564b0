// The lesson "The paper’s step response". Its texts are messages of web/locales/LANG/lessons.ftl,
// whose numbers are variables of the measurements table (web/teaching/measurements/step-
// response.csv).
export default {
  id: 'step-response',
  run: 'v=1&preset=step',
  plot: 'speed', // the true speed’s settling after the step
  holds: [
    'step.jhigh.reached == 0',
    'step.jlow.reached == 0',
    'step.rrhigh.reached == 0',
    'step.rrlow.reached == 0',
    // "leads": the error's largest positive value dwarfs its largest negative one on every draw.
    'step.perfect.jhigh.lead > 100 * -step.perfect.jhigh.lag',
    // "off by as much": the estimate's error is within 5 % of the speed's on every draw.
    'step.jhigh.est.min > 0.95 * step.jhigh.final.min',
    'step.jhigh.est.max < 1.05 * step.jhigh.final.max',
    // "because the feedforward asks for the torque of the model’s inertia": with no step to
    // feed forward, the same wrong inertia costs the perfect observer's loop almost nothing.
    'step.perfect.jhigh.nostep < 0.01 * step.perfect.jhigh.peak',
    // "at most a few samples" (50 µs each).
    'step.settle.max - step.filter < 0.0002',
  ],
  givens: [
    '0.5 rad/s step',
    '200 Hz filter',
    '50 ms',
    '45–65 ms',
    '2 %',
    '0.1 s',
    '20 % high',
    '20 % off',
    '10 % off',
    '10 % high',
    '1 s',
    'seeds 1 to',
    'k1 to 600',
  ],
};
