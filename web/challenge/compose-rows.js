// The compose form's rows: the fields a student may change with their ranges, the criteria on
// the run's figures with their bounds, and the robustness variants. Their defaults are a
// starting point for the lecturer; the core checks and writes the challenge they describe.
import { fieldValue } from '../ui/scenario.js';
import { el } from '../ui/dom.js';
import { t } from '../l10n/l10n.js';
import { sig } from '../analysis/digits.js';

/** @import * as P from '../worker/protocol.js' */

/**
 * A field of the scenario (the core's description of it), a figure a criterion may name, and the
 * measures of a run with one of its figures.
 * @typedef {P.Info['fields'][number]} Field
 * @typedef {P.Jobs['challenge-figures']['result'][number]} FigureInfo
 * @typedef {P.Jobs['challenge-run']['result']} Measures
 * @typedef {Measures['figures'][number]} Measure
 */

/**
 * `x` to two significant digits, as the codec writes numbers.
 * @param {number} x
 */
const round2 = (x) => Number(x.toPrecision(2));

/** The message saying a criterion's bound in words, by its name in the codec. @type {Record<string, string>} */
const OP_WORDS = { max: 'compose-op-max', min: 'compose-op-min', abs: 'compose-op-abs', band: 'compose-op-band' };

/**
 * A range around the field's value: half to twice it, within the field's own range.
 * @param {Field} f
 */
function rangeAround(f) {
  const v = Number(f.value);
  if (f.integer && f.min === 0 && f.max === 1) return ['0', '1'];
  let [lo, hi] = v > 0 ? [v / 2, v * 2] : v < 0 ? [v * 2, v / 2] : [f.min, f.max];
  lo = Math.max(lo, f.min);
  hi = Math.min(hi, f.max);
  if (f.integer) [lo, hi] = [Math.ceil(lo), Math.floor(hi)];
  const nice = (/** @type {number} */ x) => (Number.isFinite(x) && x !== 0 ? Number(x.toPrecision(3)) : x);
  return [String(nice(lo)), String(nice(hi))];
}

/**
 * A button that calls `onClick`.
 * @param {string} id
 * @param {string} text
 * @param {() => void} onClick
 */
export function button(id, text, onClick) {
  const b = /** @type {HTMLButtonElement} */ (el('button', { type: 'button', id, textContent: text }));
  b.addEventListener('click', onClick);
  return b;
}

/**
 * The fields a student may change: a picker and a row for each field added.
 * @param {P.Info} info
 */
export function allowSet(info) {
  /** @type {Field[]} */
  // A table of points has no range to allow.
  const fields = info.fields.filter(
    (/** @type {Field} */ f) => f.value !== null && f.acts && f.key !== 'seed' && !f.points,
  );
  const picker = /** @type {HTMLSelectElement} */ (
    el(
      'select',
      { id: 'compose-field' },
      fields.map((f) =>
        el('option', { value: f.key, textContent: t('compose-field-option', { field: f.key, doc: f.doc }) }),
      ),
    )
  );
  const rows = el('div', { id: 'compose-allow' });
  const add = button('compose-add', t('compose-add'), () => {
    const f = fields.find((x) => x.key === picker.value);
    if (f && !rows.querySelector(`[data-key="allow.${CSS.escape(f.key)}"]`)) rows.append(allowRow(f));
  });
  return el('fieldset', { className: 'compose-set' }, [
    el('legend', { textContent: t('compose-allow-legend') }),
    el('div', { className: 'buttons' }, [
      el('label', { htmlFor: 'compose-field', textContent: t('compose-field') }),
      picker,
      add,
    ]),
    rows,
  ]);
}

/**
 * The row of field `f`: its choices, or the range it may take.
 * @param {Field} f
 */
function allowRow(f) {
  const row = el('div', { className: 'compose-row' });
  row.dataset.key = `allow.${f.key}`;
  row.dataset.field = f.key;
  const id = `compose-allow-${f.key}`;
  const remove = button(`${id}-remove`, t('compose-remove'), () => row.remove());
  remove.setAttribute('aria-label', t('compose-remove.aria-label', { field: f.key }));
  if (f.formula) {
    // A step's own law: the student writes any formula (the core allows it as `formula`).
    row.append(
      el('span', { className: 'key', textContent: f.key }),
      el('input', { type: 'hidden', name: 'options', value: 'formula' }),
      el('span', { className: 'range', textContent: t('compose-allow-formula', { unit: f.unit }) }),
    );
  } else if (f.options.length) {
    row.append(
      el('label', { htmlFor: id, textContent: t('compose-allow-choices', { field: f.key }) }),
      el('input', { id, name: 'options', value: f.options.join('|') }),
    );
  } else {
    const [lo, hi] = rangeAround(f);
    row.append(
      el('span', { className: 'key', textContent: f.key }),
      el('label', { htmlFor: `${id}-lo`, textContent: t('compose-allow-from') }),
      el('input', { id: `${id}-lo`, name: 'lo', value: lo, size: 8, inputMode: 'decimal' }),
      el('label', { htmlFor: `${id}-hi`, textContent: t('compose-allow-to') }),
      el('input', { id: `${id}-hi`, name: 'hi', value: hi, size: 8, inputMode: 'decimal' }),
      el('span', {
        className: 'range',
        // The field's value in the scenario, as the settings write it; without a unit the words
        // keep their distance from the field before them.
        textContent: f.unit
          ? t('compose-allow-now-unit', { unit: f.unit, value: String(f.value) })
          : ` ${t('compose-allow-now', { value: String(f.value) })}`,
      }),
    );
  }
  row.append(remove);
  return row;
}

/**
 * The criteria: a row for each figure the core lets a criterion name (`figures`), prefilled from
 * the run's `measures` when there are some.
 * @param {FigureInfo[]} figures
 * @param {Measures | null} measures
 */
export function needSet(figures, measures) {
  const rows = el('div', { id: 'compose-need' });
  for (const fig of figures) {
    const m = measures?.figures.find((/** @type {Measure} */ x) => x.name === fig.name);
    // This scenario does not measure it (no step, no load step); a law's residual is offered
    // for a challenge that allows one, though its base has none.
    if (measures && !m && fig.name !== 'law_residual') continue;
    rows.append(needRow(fig, m));
  }
  return el('fieldset', { className: 'compose-set' }, [
    el('legend', { textContent: t('compose-need-legend') }),
    el('p', { className: 'hint', textContent: t('compose-need-hint') }),
    rows,
  ]);
}

/**
 * The row of a criterion on figure `fig`, its bound prefilled from the run's measure `m`, if any.
 * @param {FigureInfo} fig
 * @param {Measure | undefined} m
 */
function needRow(fig, m) {
  const id = `compose-need-${fig.name}`;
  const row = el('div', { className: 'compose-row' });
  row.dataset.key = `need.${fig.name}`;
  row.dataset.figure = fig.name;
  // The figure's value in this run, if measured.
  const now = m ? (m.value === Infinity ? '∞' : sig(m.value, 4)) : null;
  const args = { label: fig.label, figure: fig.name, value: now ?? '', unit: fig.unit };
  const named = now === null ? 'compose-need' : fig.unit ? 'compose-need-now-unit' : 'compose-need-now';
  // The bounds the core lets this figure take, and the one it starts with.
  const op = /** @type {HTMLSelectElement} */ (
    el(
      'select',
      { id: `${id}-op`, name: 'op' },
      fig.ops.map((o) =>
        el('option', {
          value: o,
          textContent: Object.hasOwn(OP_WORDS, o) ? t(OP_WORDS[o]) : o,
        }),
      ),
    )
  );
  op.value = fig.op;
  const bound = /** @type {HTMLInputElement} */ (
    el('input', { id: `${id}-bound`, name: 'bound', size: 8, inputMode: 'decimal' })
  );
  if (m && Number.isFinite(m.value)) bound.value = String(round2((op.value === 'min' ? 1.2 : 0.8) * Math.abs(m.value)));
  // 'band' takes no bound: its field is emptied while it is chosen, and gets its number back after.
  let kept = bound.value;
  const syncBound = () => {
    const band = op.value === 'band';
    if (band && !bound.disabled) kept = bound.value;
    bound.disabled = band;
    bound.value = band ? '' : kept;
    bound.placeholder = band ? t('compose-bound-none') : '';
  };
  op.addEventListener('change', syncBound);
  syncBound();
  row.append(
    el('label', { className: 'need-label' }, [
      el('input', { type: 'checkbox', id, name: 'use' }),
      ` ${t(named, args)}`,
    ]),
    el('label', { htmlFor: `${id}-op`, className: 'sr-only', textContent: t('compose-need-op', args) }),
    op,
    el('label', {
      htmlFor: `${id}-bound`,
      className: 'sr-only',
      textContent: t(fig.unit ? 'compose-need-bound-unit' : 'compose-need-bound', args),
    }),
    bound,
    el('span', { className: 'range', textContent: fig.unit.trim() }),
    el('label', {}, [
      el('input', { type: 'checkbox', id: `${id}-robust`, name: 'robust' }),
      ` ${t('compose-need-all-runs')}`,
    ]),
  );
  return row;
}

/**
 * The robustness variants: seeds, or settings applied on top of the student's.
 * @param {P.Info} info
 */
export function varySet(info) {
  const vary = /** @type {HTMLInputElement} */ (
    el('input', {
      id: 'compose-vary',
      size: 40,
      placeholder: t('compose-vary.placeholder'),
    })
  );
  const j = Number(fieldValue(info, 'model.j'));
  const seeds = button('compose-seeds', t('compose-vary-seeds'), () => {
    vary.value = 'seeds:2..10';
  });
  const inertia = button('compose-inertia', 'model.j ±20 %', () => {
    vary.value = `model.j=${round2(0.8 * j)}|model.j=${round2(1.2 * j)}`;
  });
  inertia.disabled = !(j > 0);
  return el('fieldset', { className: 'compose-set' }, [
    el('legend', { textContent: t('compose-vary-legend') }),
    el('label', { htmlFor: 'compose-vary', textContent: t('compose-vary') }),
    vary,
    el('div', { className: 'buttons' }, [seeds, inertia]),
  ]);
}
