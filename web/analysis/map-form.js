// The model-error map's form: its two axes and its seeds, read as the map's text and filled from
// one (a link's, a lesson's). The core checks the text; a part the form has no field for stays in
// the second axis, where the core refuses it by name.

/**
 * The text field `name` of the map's `form` (the form has one of each: axis1, axis2, seeds).
 * @param {HTMLFormElement} form
 * @param {string} name
 */
const field = (form, name) => /** @type {HTMLInputElement} */ (form.elements.namedItem(name));

/**
 * Fills `form` from a map's text `AXIS[;AXIS…][;seeds=A..B]`.
 * @param {HTMLFormElement} form
 * @param {string} text
 */
export function fillMapForm(form, text) {
  const parts = text
    .split(';')
    .map((p) => p.trim())
    .filter(Boolean);
  /** @param {string} p */
  const isSeeds = (p) => p.startsWith('seeds=');
  const [axis1 = '', ...more] = parts.filter((p) => !isSeeds(p));
  const seeds = parts.find(isSeeds);
  field(form, 'axis1').value = axis1;
  field(form, 'axis2').value = more.join(';');
  if (seeds) field(form, 'seeds').value = seeds.slice('seeds='.length);
}

/**
 * The map's text as `form` holds it.
 * @param {HTMLFormElement} form
 */
export function mapFormText(form) {
  const axes = ['axis1', 'axis2'].map((n) => field(form, n).value.trim()).filter(Boolean);
  return [...axes, `seeds=${field(form, 'seeds').value.trim()}`].join(';');
}
