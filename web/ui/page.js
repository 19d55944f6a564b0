// The page's elements, looked up once, and the message line every part of the page reports in.

/**
 * The element of index.html with `id`, of the kind `kind` (any element by default). Throws,
 * naming the id, when the page has none or one of another kind, so a renamed element fails
 * where it is looked up rather than where it is first used.
 * @template {abstract new () => HTMLElement} [K=typeof HTMLElement]
 * @param {string} id
 * @param {K} [kind]
 * @returns {InstanceType<K>}
 */
export function $(id, kind) {
  const e = document.getElementById(id);
  const want = kind ?? HTMLElement;
  if (!(e instanceof want)) throw new Error(`index.html has no ${want.name} with id '${id}'`);
  return /** @type {InstanceType<K>} */ (e);
}

export const ui = {
  preset: $('preset', HTMLSelectElement),
  presetDoc: $('preset-doc', HTMLParagraphElement),
  designDoc: $('design-doc', HTMLDivElement),
  form: $('settings', HTMLFormElement),
  run: $('run', HTMLButtonElement),
  cancel: $('cancel', HTMLButtonElement),
  progress: $('progress', HTMLProgressElement),
  status: $('status', HTMLParagraphElement),
  message: $('message', HTMLParagraphElement),
  copy: $('copy-link', HTMLButtonElement),
  csv: $('export-csv', HTMLButtonElement),
  png: $('export-png', HTMLButtonElement),
  plots: $('plots', HTMLDivElement),
  present: $('present', HTMLButtonElement),
  inspect: $('inspect'),
  settingsToggle: $('settings-toggle', HTMLButtonElement),
  embed: $('copy-embed', HTMLButtonElement),
  fullRun: $('full-run', HTMLButtonElement),
  fit: $('fit', HTMLInputElement),
  fitLabel: $('fit-label', HTMLSpanElement),
  unrun: $('unrun', HTMLParagraphElement),
  figures: $('figures', HTMLDListElement),
  consistency: $('consistency', HTMLParagraphElement),
  keyFigures: $('key-figures', HTMLParagraphElement),
  figuresBar: /** @type {HTMLElement} */ (document.querySelector('.figures-bar')),
  figuresToggle: $('figures-toggle', HTMLButtonElement),
};

/**
 * Shows `text` in the message line as an error or as `info`; an empty text clears it.
 * @param {string} text
 * @param {string} [kind]
 */
export function say(text, kind = 'error') {
  ui.message.textContent = text;
  ui.message.className = text ? kind : '';
}
