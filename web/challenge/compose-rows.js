// The compose form's rows: the fields a student may change with their ranges, the criteria on
// the run's figures with their bounds, and the robustness variants. Their defaults are a
// starting point for the lecturer; the core checks and writes the challenge they describe.
import { fieldValue } from '../ui/scenario.js';
import { el } from '../ui/dom.js';

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

/** A criterion's bound in words, by its name in the codec. @type {Record<string, string>} */
const OP_WORDS = { max: 'at most', min: 'at least', abs: '|value| at most', band: 'inside its 95 % band' };

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
  const fields = info.fields.filter((/** @type {Field} */ f) => f.value !== null && f.acts && f.key !== 'seed');
  const picker = /** @type {HTMLSelectElement} */ (
    el(
      'select',
      { id: 'compose-field' },
      fields.map((f) => el('option', { value: f.key, textContent: `${f.key} — ${f.doc}` })),
    )
  );
  const rows = el('div', { id: 'compose-allow' });
  const add = button('compose-add', 'Add', () => {
    const f = fields.find((x) => x.key === picker.value);
    if (f && !rows.querySelector(`[data-key="allow.${CSS.escape(f.key)}"]`)) rows.append(allowRow(f));
  });
  return el('fieldset', { className: 'compose-set' }, [
    el('legend', { textContent: 'Fields the student may change' }),
    el('div', { className: 'buttons' }, [el('label', { htmlFor: 'compose-field', textContent: 'Field' }), picker, add]),
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
  const remove = button(`${id}-remove`, 'Remove', () => row.remove());
  remove.setAttribute('aria-label', `Remove ${f.key}`);
  const unit = f.unit ? ` ${f.unit}` : '';
  if (f.formula) {
    // A step's own law: the student writes any formula (the core allows it as `formula`).
    row.append(
      el('span', { className: 'key', textContent: f.key }),
      el('input', { type: 'hidden', name: 'options', value: 'formula' }),
      el('span', { className: 'range', textContent: `a formula of the student’s own (${f.unit})` }),
    );
  } else if (f.options.length) {
    row.append(
      el('label', { htmlFor: id, textContent: `${f.key}: choices (a|b)` }),
      el('input', { id, name: 'options', value: f.options.join('|') }),
    );
  } else {
    const [lo, hi] = rangeAround(f);
    row.append(
      el('span', { className: 'key', textContent: f.key }),
      el('label', { htmlFor: `${id}-lo`, textContent: 'from' }),
      el('input', { id: `${id}-lo`, name: 'lo', value: lo, size: 8, inputMode: 'decimal' }),
      el('label', { htmlFor: `${id}-hi`, textContent: 'to' }),
      el('input', { id: `${id}-hi`, name: 'hi', value: hi, size: 8, inputMode: 'decimal' }),
      el('span', { className: 'range', textContent: `${unit.trim()} (now ${f.value})` }),
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
    el('legend', { textContent: 'Criteria: the figures of this run' }),
    el('p', {
      className: 'hint',
      textContent: '“All runs” makes the criterion hold on every variant too (the worst run counts).',
    }),
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
  const unit = fig.unit ? ` ${fig.unit}` : '';
  const now = m ? ` — now ${m.value === Infinity ? '∞' : Number(m.value.toPrecision(4))}${unit}` : '';
  // The bounds the core lets this figure take, and the one it starts with.
  const op = /** @type {HTMLSelectElement} */ (
    el(
      'select',
      { id: `${id}-op`, name: 'op' },
      fig.ops.map((o) =>
        el('option', {
          value: o,
          textContent: OP_WORDS[o] ?? o,
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
    bound.placeholder = band ? 'none' : '';
  };
  op.addEventListener('change', syncBound);
  syncBound();
  row.append(
    el('label', { className: 'need-label' }, [
      el('input', { type: 'checkbox', id, name: 'use' }),
      ` ${fig.label} (${fig.name})${now}`,
    ]),
    el('label', { htmlFor: `${id}-op`, className: 'sr-only', textContent: `${fig.name}: how it is bounded` }),
    op,
    el('label', { htmlFor: `${id}-bound`, className: 'sr-only', textContent: `${fig.name}: bound${unit}` }),
    bound,
    el('span', { className: 'range', textContent: unit.trim() }),
    el('label', {}, [el('input', { type: 'checkbox', id: `${id}-robust`, name: 'robust' }), ' all runs']),
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
      placeholder: 'seeds:2..10  or  model.j=0.016|model.j=0.024',
    })
  );
  const j = Number(fieldValue(info, 'model.j'));
  const seeds = button('compose-seeds', 'Seeds 2 to 10', () => {
    vary.value = 'seeds:2..10';
  });
  const inertia = button('compose-inertia', 'model.j ±20 %', () => {
    vary.value = `model.j=${round2(0.8 * j)}|model.j=${round2(1.2 * j)}`;
  });
  inertia.disabled = !(j > 0);
  return el('fieldset', { className: 'compose-set' }, [
    el('legend', { textContent: 'Robustness variants (optional)' }),
    el('label', {
      htmlFor: 'compose-vary',
      textContent: 'Variants: seeds:A..B, or settings applied on top of the student’s, separated by |',
    }),
    vary,
    el('div', { className: 'buttons' }, [seeds, inertia]),
  ]);
}
