// The lesson "The paper’s step response". Numbers are placeholders of the measurements table
// (web/teaching/measurements/step-response.csv); see web/teaching/measured.js.
export default {
  id: 'step-response',
  run: 'v=1&preset=step',
  plot: 'speed', // the true speed’s settling after the step
  title: 'The paper’s step response',
  look: 'A 0.5 rad/s step, filtered by a critically damped 200 Hz filter, starts at 50 ms. Drag across 45–65 ms on the speed plot: the true speed follows the filtered reference. The ω − ω_d plot shows the error during the step; the figures strip gives the 2 % settling time and the peak error over the preset’s 0.1 s.',
  question:
    'The reference filter alone settles (to 2 %) in {step.filter} ms. What is the 2 % settling time of the true speed, and how much does the controller with its observer add? Does that hold if the model’s inertia is off?',
  hint: 'Read “2 % settling time of ω after the step” in the figures strip and compare it with the filter’s {step.filter} ms; change the noise seed (settings, Noise and seed) and read it again. Then set model.j = 0.024 (the model’s inertia 20 % high) in the settings and run again, once with the EKF and once with a perfect observer (perfect = 1).',
  answer:
    'Ranges are over {step.settle.min#draws} noise draws (seeds 1 to {step.settle.min#draws}). With an exact model the true speed settles in {step.settle.min} to {step.settle.max} ms, against the filter’s {step.filter} ms: the loop adds at most a few samples. The tracking is the feedforward’s: the controller feeds ω̇_d and ω̈_d forward, and halving k1 to 600 leaves the settling time at {step.k1half.min} to {step.k1half.max} ms. That needs an exact model: with the model’s inertia 20 % off either way, or the motor’s rotor resistance 10 % off either way, the preset’s 0.1 s ends with a settling time on {step.jhigh.reached} and {step.jlow.reached} of the {step.jhigh.reached#draws} draws with the inertia high and low, and on {step.rrhigh.reached} and {step.rrlow.reached} with the resistance high and low. With the model’s inertia 20 % high (model.j = 0.024) the speed is still {step.jhigh.final.min} to {step.jhigh.final.max} rad/s high at the end of the 0.1 s, and the speed estimate is off by as much ({step.jhigh.est.min} to {step.jhigh.est.max} rad/s); over 1 s (duration = 1) the speed enters the 2 % band for good {step.jhigh1s.min} to {step.jhigh1s.max} ms after the step. A perfect observer does not save the controller from a wrong inertia: with the same model.j = 0.024 and perfect = 1 the speed leads its reference by up to {step.perfect.jhigh.peak} mrad/s, at least {step.perfect.ratio} times the exact model’s peak error, because the feedforward asks for the torque of the model’s inertia, not the motor’s. With the motor’s rotor resistance 10 % high (plant.rr = 5.445) the step runs away on {step.rrhigh.runaway} of the {step.rrhigh.runaway#draws} draws (the lesson on low speed shows where the filter loses the speed).',
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
