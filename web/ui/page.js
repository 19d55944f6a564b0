// The page's elements, looked up once, and the message line every part of the page reports in.

/**
 * The element of index.html with `id`. Typed loosely: its kind (input, select, form, …) is the
 * HTML's, which the compiler does not read.
 * @param {string} id
 * @returns {any}
 */
export const $ = (id) => document.getElementById(id);

export const ui = {
  preset: $('preset'),
  presetDoc: $('preset-doc'),
  form: $('settings'),
  run: $('run'),
  cancel: $('cancel'),
  progress: $('progress'),
  status: $('status'),
  message: $('message'),
  copy: $('copy-link'),
  csv: $('export-csv'),
  png: $('export-png'),
  plots: $('plots'),
  present: $('present'),
  inspect: $('inspect'),
  settingsToggle: $('settings-toggle'),
  embed: $('copy-embed'),
  fullRun: $('full-run'),
  fit: $('fit'),
  fitLabel: $('fit-label'),
  unrun: $('unrun'),
  figures: $('figures'),
  consistency: $('consistency'),
  keyFigures: $('key-figures'),
  figuresBar: /** @type {HTMLElement} */ (document.querySelector('.figures-bar')),
  figuresToggle: $('figures-toggle'),
};

/** Shows `text` in the message line as an error or as `info`; an empty text clears it. */
export function say(text, kind = 'error') {
  ui.message.textContent = text;
  ui.message.className = text ? kind : '';
}
