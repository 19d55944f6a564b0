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

/** Renders `info.fields` into `form`, keeping which groups are open. */
export function renderFields(form, info) {
  const open = new Set([...form.querySelectorAll('details[open]')].map((d) => d.dataset.group));
  const first = form.childElementCount === 0;
  form.replaceChildren();
  for (const [group, title] of Object.entries(GROUPS)) {
    const fields = info.fields.filter((f) => f.group === group && f.value !== null);
    if (!fields.length) continue;
    const details = el('details', { open: first ? OPEN_GROUPS.has(group) : open.has(group) });
    details.dataset.group = group;
    details.append(el('summary', { textContent: title }));
    // A field that does not act on this scenario keeps its value (it stays in the scenario
    // string) but is not shown.
    for (const f of fields) {
      const control = fieldControl(f, 'field');
      control.hidden = !f.acts;
      details.append(control);
    }
    details.hidden = fields.every((f) => !f.acts);
    form.append(details);
  }
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

/** The scenario string the form describes: the preset plus every field shown. */
export function composeScenario(form, preset) {
  const parts = ['v=1', `preset=${preset}`];
  for (const control of form.querySelectorAll('input, select')) {
    // A formula as typed: the core's positions in it are those the walkthrough's preview marks.
    const value =
      control.type === 'checkbox'
        ? control.checked
          ? '1'
          : '0'
        : control.classList.contains('formula')
          ? control.value
          : control.value.trim();
    parts.push(`${control.name}=${encodeURIComponent(value)}`);
  }
  return parts.join('&');
}

/** Marks the field a codec error message names (`field 'k1' ...`), clearing the others. */
export function markInvalid(form, message) {
  const match = /field '([^']+)'/.exec(message ?? '');
  for (const control of form.querySelectorAll('input, select')) {
    control.classList.toggle('invalid', match !== null && control.name === match[1]);
  }
}

/** Copies a knob's value into the settings form's control for the same field and reports a change. */
export function forwardKnob(form, knob) {
  const target = form.elements.namedItem(knob.name);
  if (!target) return;
  if (knob.type === 'checkbox') target.checked = knob.checked;
  else target.value = knob.value;
  form.dispatchEvent(new Event('change'));
}

/** The value the form holds for `key`, as the codec writes it. */
export function fieldValue(info, key) {
  return info.fields.find((f) => f.key === key)?.value ?? null;
}
