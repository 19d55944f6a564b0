// The model-error map's form: its two axes and its seeds, filled from a map's parts as the core
// reads them from a text (a link's, a lesson's), and read back as parts for the core to check.

/** @import * as P from '../worker/protocol.js' */

/**
 * The text field `name` of the map's `form` (the form has one of each: axis1, axis2, seeds).
 * @param {HTMLFormElement} form
 * @param {string} name
 */
const field = (form, name) => /** @type {HTMLInputElement} */ (form.elements.namedItem(name));

/**
 * Fills `form` from a map's parts: the first axis in the first field, any others in the second
 * (where the core refuses a third by name), the seeds when given.
 * @param {HTMLFormElement} form
 * @param {P.Jobs['map-parts']['result']} parts
 */
export function fillMapForm(form, { axes: [axis1 = '', ...more], seeds }) {
  field(form, 'axis1').value = axis1;
  field(form, 'axis2').value = more.join(';');
  if (seeds !== null) field(form, 'seeds').value = seeds;
}

/**
 * The map's parts as `form` holds them: the axes' texts and the seeds' range (null when empty).
 * @param {HTMLFormElement} form
 */
export function mapFormParts(form) {
  const axes = ['axis1', 'axis2'].map((n) => field(form, n).value);
  const seeds = field(form, 'seeds').value.trim();
  return { axes, seeds: seeds === '' ? null : seeds };
}
