// The guided lessons, in order: the run a lesson opens (a preset, with overrides where the lesson
// needs a longer run or another setting) and the plot its question is about. What a student reads
// (the title, what to look for, a question that the page's figures answer, a hint, and the answer
// for the lecturer) are the messages `ID-title`, `ID-look`, … of web/locales/LANG/lessons.ftl,
// whose numbers are variables naming measurements of the table in web/teaching/measurements/
// (web/teaching/measured.js). A lesson's `holds` lists the conclusions its words state, each
// checked on the table by tests/measurements.test.mjs, and its `givens` the settings its English
// words name. A lesson's `id` is its link's name (`#lesson=ID`), which never changes: a link to a
// lesson outlives lessons added or reordered.
import stepResponse from './lesson-text/step-response.js';
import tracking200hz from './lesson-text/tracking-200hz.js';
import observerBias from './lesson-text/observer-bias.js';
import rrMismatch from './lesson-text/rr-mismatch.js';
import loadStep from './lesson-text/load-step.js';
import loadEstimate from './lesson-text/load-estimate.js';
import rrEstimate from './lesson-text/rr-estimate.js';
import ifocBaseline from './lesson-text/ifoc-baseline.js';
import realDrive from './lesson-text/real-drive.js';
import highGain from './lesson-text/high-gain.js';
import lowSpeed from './lesson-text/low-speed.js';
import modelExactness from './lesson-text/model-exactness.js';
import deriveSteps from './lesson-text/derive-steps.js';
import robustTerms from './lesson-text/robust-terms.js';
import ownMotor from './lesson-text/own-motor.js';

/**
 * A lesson: its link's name, its run, the conclusions its texts state
 * and the settings they name, the tab it opens (the Trajectories tab otherwise), the model-error
 * map it fills in, and the plot its question is about: the `data-plot` id of a plot in that tab (a
 * trajectory plot's id, a walkthrough plot's `SECTION-KEY`, or `map`), which presentation mode
 * shows whole beside the question.
 * @typedef {{id: string, run: string,
 *   holds: string[], givens: string[], tab?: string, map?: string, plot: string}} Lesson
 */

/** @type {Lesson[]} */
export const LESSONS = [
  stepResponse,
  tracking200hz,
  observerBias,
  rrMismatch,
  loadStep,
  loadEstimate,
  rrEstimate,
  ifocBaseline,
  realDrive,
  highGain,
  lowSpeed,
  modelExactness,
  deriveSteps,
  robustTerms,
  ownMotor,
];
