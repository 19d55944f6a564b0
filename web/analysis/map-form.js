// The model-error map's form: its two axes and its seeds, read as the map's text and filled from
// one (a link's, a lesson's). The core checks the text; a part the form has no field for stays in
// the second axis, where the core refuses it by name.

/** Fills `form` from a map's text `AXIS[;AXIS…][;seeds=A..B]`. */
export function fillMapForm(form, text) {
  const parts = text
    .split(';')
    .map((p) => p.trim())
    .filter(Boolean);
  const isSeeds = (p) => p.startsWith('seeds=');
  const [axis1 = '', ...more] = parts.filter((p) => !isSeeds(p));
  const seeds = parts.find(isSeeds);
  form.elements.namedItem('axis1').value = axis1;
  form.elements.namedItem('axis2').value = more.join(';');
  if (seeds) form.elements.namedItem('seeds').value = seeds.slice('seeds='.length);
}

/** The map's text as `form` holds it. */
export function mapFormText(form) {
  const f = form.elements;
  const axes = ['axis1', 'axis2'].map((n) => f.namedItem(n).value.trim()).filter(Boolean);
  return [...axes, `seeds=${f.namedItem('seeds').value.trim()}`].join(';');
}
