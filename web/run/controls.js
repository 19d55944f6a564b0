// Settings form generated from the core's field table (key, unit, range, meaning, value).
// Text from the URL or the core only ever reaches the page through textContent and values.
import { el } from '../ui/dom.js';
import { verdictLine } from '../ui/verdict-line.js';
import { t } from '../l10n/l10n.js';
import { local } from '../plots/numbers.js';

/** @import * as P from '../worker/protocol.js' */

/**
 * A field of the core's description, one of those with a value (the ones the form holds), and a
 * field's control in the form or a walkthrough knob.
 * @typedef {P.Info['fields'][number]} Field
 * @typedef {Field & {value: string}} HeldField
 * @typedef {HTMLInputElement | HTMLSelectElement} Control
 */

// The form's groups, in order; each group's title is the message `settings-group-GROUP`.
const GROUPS = [
  'reference',
  'controller',
  'gains',
  'observer',
  'noise',
  'plant',
  'model',
  'load',
  'limits',
  'drive',
  'law',
];
const OPEN_GROUPS = new Set(['reference', 'controller', 'gains']);

/**
 * The values field `f` allows, in words.
 * @param {Field} f
 */
function allowed(f) {
  if (f.options.length) return f.options.join(' | ');
  if (f.formula) return t('settings-allowed-formula');
  if (f.points)
    return t('settings-allowed-table', {
      points: f.points,
      min: local(String(f.min)),
      max: `${local(String(f.max))} ${f.unit}`,
    });
  return t(f.integer ? 'settings-allowed-whole' : 'settings-allowed-range', {
    min: local(String(f.min)),
    op: f.min_open ? '<' : '≤',
    key: f.key,
    max: `${local(String(f.max))}${f.unit ? ` ${f.unit}` : ''}`,
  });
}

/**
 * The input or select of field `f`, holding its value.
 * @param {Field} f
 * @returns {Control}
 */
function input(f) {
  // Only a field with a value gets a control: the form and the knobs leave the others out.
  const value = /** @type {string} */ (f.value);
  if (f.options.length) {
    const select = el('select', { name: f.key });
    for (const o of f.options) select.append(el('option', { value: o, textContent: o }));
    select.value = value;
    return select;
  }
  if (f.formula) {
    return el('input', {
      type: 'text',
      name: f.key,
      value,
      className: 'formula',
      spellcheck: false,
      autocomplete: 'off',
      autocapitalize: 'off',
    });
  }
  if (f.points) return el('input', { type: 'text', name: f.key, value, spellcheck: false, autocomplete: 'off' });
  if (f.integer && f.min === 0 && f.max === 1) {
    return el('input', { type: 'checkbox', name: f.key, checked: value === '1' });
  }
  return el('input', {
    type: 'text',
    inputMode: 'decimal',
    name: f.key,
    value,
    spellcheck: false,
  });
}

/**
 * The description each form shows: the fields of a group not built yet are read from it.
 * @type {WeakMap<HTMLFormElement, P.Info>}
 */
const shown = new WeakMap();

/**
 * The fields of `info` in `group` that the form holds (a field with no value is not in the scenario).
 * @param {P.Info} info
 * @param {string} group
 * @returns {HeldField[]}
 */
const fieldsOf = (info, group) =>
  info.fields.filter(/** @returns {f is HeldField} */ (f) => f.group === group && f.value !== null);

/**
 * The form's control of field `key` (its input or select), or null when it has none.
 * @param {HTMLFormElement} form
 * @param {string} key
 */
function namedControl(form, key) {
  const control = form.elements.namedItem(key);
  return control instanceof HTMLInputElement || control instanceof HTMLSelectElement ? control : null;
}

/**
 * Builds the fields of group `details` of `form`, once. A field that does not act on this
 * scenario keeps its value (it stays in the scenario string) but is not shown.
 * @param {HTMLFormElement} form
 * @param {HTMLDetailsElement} details
 */
function fill(form, details) {
  if (details.dataset.built !== undefined) return;
  details.dataset.built = '';
  // A group is made by `renderFields`, which names it and keeps the description it shows.
  const info = /** @type {P.Info} */ (shown.get(form));
  for (const f of fieldsOf(info, /** @type {string} */ (details.dataset.group))) {
    const control = fieldControl(f, 'field');
    control.hidden = !f.acts;
    // A step's own law: its verdict after a run, as in the walkthrough's step.
    const step = f.formula;
    if (step) {
      // The walkthrough's step announces the same verdict: this copy is not announced.
      const line = verdictLine(step, true);
      const scope = el('div', { className: 'law-field' }, [control, line]);
      scope.dataset.lawScope = '';
      scope.hidden = control.hidden;
      details.append(scope);
    } else details.append(control);
  }
}

/**
 * Builds the groups of `form` not built yet (of `groups`, else all); says so with a `fieldsbuilt`
 * event on the form (an open challenge then locks their fields).
 * @param {HTMLFormElement} form
 * @param {Iterable<HTMLDetailsElement>} [groups]
 */
export function buildGroups(form, groups = form.querySelectorAll('details')) {
  const unbuilt = [...groups].filter((details) => details.dataset.built === undefined);
  unbuilt.forEach((details) => fill(form, details));
  if (unbuilt.length) form.dispatchEvent(new Event('fieldsbuilt'));
}

/**
 * Renders `info.fields` into `form`, keeping which groups are open. The open groups' fields are
 * built at once; the closed ones' when one is opened, when a field of theirs is needed (a knob's
 * edit, a challenge's control, an error to mark), or by `buildGroups` (once a run is drawn
 * and the page is idle): most of the form is closed, and the first run need not wait for it.
 * @param {HTMLFormElement} form
 * @param {P.Info} info
 */
export function renderFields(form, info) {
  const openGroups = /** @type {NodeListOf<HTMLDetailsElement>} */ (form.querySelectorAll('details[open]'));
  const open = new Set([...openGroups].map((d) => d.dataset.group));
  const first = form.childElementCount === 0;
  shown.set(form, info);
  form.replaceChildren();
  for (const group of GROUPS) {
    const fields = fieldsOf(info, group);
    if (!fields.length) continue;
    const details = el('details', { open: first ? OPEN_GROUPS.has(group) : open.has(group) });
    details.dataset.group = group;
    const summary = el('summary', { textContent: t(`settings-group-${group}`) });
    // Built as it is opened: on the click (by the pointer or the keyboard), before it is drawn
    // open, or as it opens otherwise.
    summary.addEventListener('click', () => buildGroups(form, [details]));
    details.addEventListener('toggle', () => details.open && buildGroups(form, [details]));
    details.append(summary);
    if (details.open) fill(form, details);
    details.hidden = fields.every((f) => !f.acts);
    form.append(details);
  }
}

/**
 * Sets `control` to `value` as the scenario string holds it (a checkbox's '0' or '1').
 * @param {Control} control
 * @param {string} value
 */
function write(control, value) {
  if (control instanceof HTMLInputElement && control.type === 'checkbox') control.checked = value === '1';
  else control.value = value;
}

/**
 * Shows the values of `info` in the form's built controls, except the one being edited.
 * @param {HTMLFormElement} form
 * @param {P.Info} info
 */
export function syncFields(form, info) {
  shown.set(form, info);
  for (const f of info.fields) {
    if (f.value === null) continue;
    const control = namedControl(form, f.key);
    if (control && control !== document.activeElement) write(control, f.value);
  }
}

/**
 * The form's control of field `key`, the closed groups built first if need be (null if it has none).
 * @param {HTMLFormElement} form
 * @param {string} key
 */
function controlOf(form, key) {
  if (!namedControl(form, key)) buildGroups(form);
  return namedControl(form, key);
}

/**
 * A labelled control for field `f` (one with a value) with id `${prefix}-${key}`, showing its
 * unit and range.
 * @param {Field} f
 * @param {string} prefix
 */
export function fieldControl(f, prefix) {
  const control = input(f);
  control.id = `${prefix}-${f.key}`;
  control.title = t('settings-allowed', { values: allowed(f) });
  const unit = f.unit ? ` (${f.unit})` : '';
  return el('label', { htmlFor: control.id, className: 'field' }, [
    el('span', { className: 'key', textContent: f.key }),
    el('span', { className: 'doc', textContent: `${f.doc}${unit}` }),
    control,
    el('span', { className: 'range', textContent: allowed(f) }),
  ]);
}

/**
 * A control's value as the scenario string holds it.
 * @param {Control} control
 */
function valueOf(control) {
  if (control instanceof HTMLInputElement && control.type === 'checkbox') return control.checked ? '1' : '0';
  // A formula as typed: the core's positions in it are those the walkthrough's preview marks.
  return control.classList.contains('formula') ? control.value : control.value.trim();
}

/**
 * The scenario the form describes, for the core to write and check: the preset, and every field
 * the form holds, in the form's order, each as its control holds it (as the description says
 * where the group is not built).
 * @param {HTMLFormElement} form
 * @param {string} preset
 * @returns {import('../worker/protocol.js').FormScenario}
 */
export function formScenario(form, preset) {
  const info = shown.get(form);
  const held = (/** @type {Field} */ f) => {
    const control = namedControl(form, f.key);
    return control ? valueOf(control) : String(f.value);
  };
  // A field changed here whose new value sets others afresh (the core's `resets`: a reference kind
  // its parameters, a motor the plant, the model and the rating) leaves their old values out.
  const reset = new Set(
    (info?.fields ?? []).filter((f) => f.value !== null && held(f) !== f.value).flatMap((f) => f.resets),
  );
  /** @type {[string, string][]} */
  const fields = [];
  for (const group of GROUPS) {
    for (const f of info ? fieldsOf(info, group) : []) if (!reset.has(f.key)) fields.push([f.key, held(f)]);
  }
  return { preset, fields };
}

/**
 * Marks the control of field `key` (the field the core refused; null for none), clearing the
 * others.
 * @param {HTMLFormElement} form
 * @param {string | null} key
 */
export function markInvalid(form, key) {
  if (key !== null) controlOf(form, key);
  for (const control of form.querySelectorAll('input, select')) {
    control.classList.toggle('invalid', key !== null && /** @type {HTMLInputElement} */ (control).name === key);
  }
}

/**
 * Sets the form's control of field `key` (if it has one) to `value` as the scenario string holds it.
 * @param {HTMLFormElement} form
 * @param {string} key
 * @param {string} value
 */
export function setField(form, key, value) {
  const target = controlOf(form, key);
  if (target) write(target, value);
}

/**
 * Copies a knob's value into the settings form's control for the same field and reports a change.
 * @param {HTMLFormElement} form
 * @param {Control} knob
 */
export function forwardKnob(form, knob) {
  const target = controlOf(form, knob.name);
  if (!target) return;
  write(target, valueOf(knob));
  form.dispatchEvent(new Event('change'));
}
