// Settings form generated from the core's field table (key, unit, range, meaning, value).
// Text from the URL or the core only ever reaches the page through textContent and values.
import { el } from '../ui/dom.js';

const GROUPS = {
  reference: 'Reference',
  controller: 'Controller: backstepping or classical IFOC',
  gains: 'Backstepping gains',
  observer: 'Observer (EKF)',
  noise: 'Noise and seed',
  plant: 'Plant: the simulated motor',
  model: 'Model: what the EKF and controller assume',
  load: 'Unknown load step',
  limits: 'Voltage limit (box), rating, duration and timing',
  drive: 'Drive: computation delay, inverter limit and PWM',
  law: 'Your own laws for the backstepping steps (empty: the paper’s)',
};
const OPEN_GROUPS = new Set(['reference', 'controller', 'gains']);

function allowed(f) {
  if (f.options.length) return f.options.join(' | ');
  if (f.formula) return 'a formula of the names the walkthrough’s “Write this step” lists; empty: the paper’s law';
  const lo = f.min_open ? '<' : '≤';
  const unit = f.unit ? ` ${f.unit}` : '';
  return `${f.min} ${lo} ${f.key} ≤ ${f.max}${unit}${f.integer ? ', whole number' : ''}`;
}

function input(f) {
  if (f.options.length) {
    const select = el('select', { name: f.key });
    for (const o of f.options) select.append(el('option', { value: o, textContent: o }));
    select.value = f.value;
    return select;
  }
  if (f.formula) {
    return el('input', {
      type: 'text',
      name: f.key,
      value: f.value,
      className: 'formula',
      spellcheck: false,
      autocomplete: 'off',
      autocapitalize: 'off',
    });
  }
  if (f.integer && f.min === 0 && f.max === 1) {
    return el('input', { type: 'checkbox', name: f.key, checked: f.value === '1' });
  }
  return el('input', {
    type: 'text',
    inputMode: 'decimal',
    name: f.key,
    value: f.value,
    spellcheck: false,
  });
}

/** The description each form shows: the fields of a group not built yet are read from it. */
const shown = new WeakMap();

/** The fields of `info` in `group` that the form holds (a field with no value is not in the scenario). */
const fieldsOf = (info, group) => info.fields.filter((f) => f.group === group && f.value !== null);

/**
 * Builds the fields of group `details` of `form`, once. A field that does not act on this
 * scenario keeps its value (it stays in the scenario string) but is not shown.
 */
function fill(form, details) {
  if (details.dataset.built !== undefined) return;
  details.dataset.built = '';
  for (const f of fieldsOf(shown.get(form), details.dataset.group)) {
    const control = fieldControl(f, 'field');
    control.hidden = !f.acts;
    details.append(control);
  }
}

/**
 * Builds the groups of `form` not built yet (of `groups`, else all); says so with a `fieldsbuilt`
 * event on the form (an open challenge then locks their fields).
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
 */
export function renderFields(form, info) {
  const open = new Set([...form.querySelectorAll('details[open]')].map((d) => d.dataset.group));
  const first = form.childElementCount === 0;
  shown.set(form, info);
  form.replaceChildren();
  for (const [group, title] of Object.entries(GROUPS)) {
    const fields = fieldsOf(info, group);
    if (!fields.length) continue;
    const details = el('details', { open: first ? OPEN_GROUPS.has(group) : open.has(group) });
    details.dataset.group = group;
    const summary = el('summary', { textContent: title });
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

/** Sets `control` to `value` as the scenario string holds it (a checkbox's '0' or '1'). */
function write(control, value) {
  if (control.type === 'checkbox') control.checked = value === '1';
  else control.value = value;
}

/** Shows the values of `info` in the form's built controls, except the one being edited. */
export function syncFields(form, info) {
  shown.set(form, info);
  for (const f of info.fields) {
    const control = f.value === null ? null : form.elements.namedItem(f.key);
    if (control && control !== document.activeElement) write(control, f.value);
  }
}

/** The form's control of field `key`, the closed groups built first if need be (null if it has none). */
function controlOf(form, key) {
  if (!form.elements.namedItem(key)) buildGroups(form);
  return form.elements.namedItem(key);
}

/** A labelled control for field `f` with id `${prefix}-${key}`, showing its unit and range. */
export function fieldControl(f, prefix) {
  const control = input(f);
  control.id = `${prefix}-${f.key}`;
  control.title = `allowed: ${allowed(f)}`;
  const unit = f.unit ? ` (${f.unit})` : '';
  return el('label', { htmlFor: control.id, className: 'field' }, [
    el('span', { className: 'key', textContent: f.key }),
    el('span', { className: 'doc', textContent: `${f.doc}${unit}` }),
    control,
    el('span', { className: 'range', textContent: allowed(f) }),
  ]);
}

/** A control's value as the scenario string holds it. */
function valueOf(control) {
  if (control.type === 'checkbox') return control.checked ? '1' : '0';
  // A formula as typed: the core's positions in it are those the walkthrough's preview marks.
  return control.classList.contains('formula') ? control.value : control.value.trim();
}

/**
 * The scenario string the form describes: the preset plus every field it holds, in the form's
 * order, each as its control holds it (as the description says where the group is not built).
 */
export function composeScenario(form, preset) {
  const info = shown.get(form);
  const parts = ['v=1', `preset=${preset}`];
  for (const group of Object.keys(GROUPS)) {
    for (const f of info ? fieldsOf(info, group) : []) {
      const control = form.elements.namedItem(f.key);
      parts.push(`${f.key}=${encodeURIComponent(control ? valueOf(control) : f.value)}`);
    }
  }
  return parts.join('&');
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

/** Sets the form's control of field `key` (if it has one) to `value` as the scenario string holds it. */
export function setField(form, key, value) {
  const target = controlOf(form, key);
  if (target) write(target, value);
}

/** Copies a knob's value into the settings form's control for the same field and reports a change. */
export function forwardKnob(form, knob) {
  const target = controlOf(form, knob.name);
  if (!target) return;
  write(target, valueOf(knob));
  form.dispatchEvent(new Event('change'));
}
