// The Challenge tab, for the lecturer: composes a challenge from the scenario in the form (its
// base), the fields a student may change with their ranges, criteria on the figures of the
// current run with their bounds, and robustness variants. The core checks the link and writes
// it and the task in words, both to copy; its message names the field at fault.
import { $ } from '../ui/page.js';
import { fieldValue } from '../run/controls.js';
import { presetNamed } from '../ui/url.js';
import { el } from '../ui/dom.js';

/** `x` to two significant digits, as the codec writes numbers. */
const round2 = (x) => Number(x.toPrecision(2));

// Final values are bounded on both sides; the mean NIS by its band.
const ABS = new Set(['speed_error_final', 'flux_error_final', 'speed_estimate_error_final']);

/** A range around the field's value: half to twice it, within the field's own range. */
function rangeAround(f) {
  const v = Number(f.value);
  if (f.integer && f.min === 0 && f.max === 1) return [0, 1];
  let [lo, hi] = v > 0 ? [v / 2, v * 2] : v < 0 ? [v * 2, v / 2] : [f.min, f.max];
  lo = Math.max(lo, f.min);
  hi = Math.min(hi, f.max);
  if (f.integer) [lo, hi] = [Math.ceil(lo), Math.floor(hi)];
  const nice = (x) => (Number.isFinite(x) && x !== 0 ? Number(x.toPrecision(3)) : x);
  return [nice(lo), nice(hi)];
}

/** The compose form in `box`; `client` is the page's worker and `state` the page's state. */
export function createCompose({ client, state }) {
  const box = $('compose');
  const status = el('p', { id: 'compose-status', className: 'hint', role: 'status' });
  const error = el('p', { id: 'compose-error', className: 'challenge-error', role: 'alert', hidden: true });
  const output = el('div', { id: 'compose-output', hidden: true });
  let figures = null; // what criteria may name, from the core
  let base = null; // the scenario the form was filled from

  async function fill() {
    const info = state.info;
    if (!info) return;
    figures ??= await client.job('challenge-figures');
    // The figures of the run on screen, when it is the form's scenario.
    let measures = null;
    if (state.ranScenario === info.encoded && !state.running && state.runId > 0)
      measures = await client.measure(state.runId).catch(() => null);
    base = info;
    output.hidden = true;
    fail('');
    box.replaceChildren(
      el('p', {
        className: 'hint',
        textContent:
          'The challenge starts from the scenario in the settings (its base); the student may change only the fields listed here, within their ranges, and passes when every criterion holds. Set the scenario up and run it first: the criteria are prefilled from its figures, 20 % tighter than this run.',
      }),
      el('p', { className: 'compose-base' }, ['Base: ', el('code', { textContent: info.encoded })]),
      el('label', { className: 'compose-title' }, [
        'Title ',
        el('input', { id: 'compose-title', value: `Challenge: ${presetNamed(info.encoded)}`, maxLength: 120 }),
      ]),
      allowSet(info),
      needSet(measures),
      varySet(info),
      el('div', { className: 'buttons' }, [button('compose-make', 'Make the challenge link', make)]),
      error,
      output,
    );
    status.textContent = measures
      ? ''
      : 'No finished run of this scenario to take the figures from: run it, then press “Fill from the current scenario” again.';
    box.prepend(status);
    document.body.dataset.compose = 'filled';
  }

  function button(id, text, onClick) {
    const b = el('button', { type: 'button', id, textContent: text });
    b.addEventListener('click', onClick);
    return b;
  }

  function allowSet(info) {
    const fields = info.fields.filter((f) => f.value !== null && f.acts && f.key !== 'seed');
    const picker = el(
      'select',
      { id: 'compose-field' },
      fields.map((f) => el('option', { value: f.key, textContent: `${f.key} — ${f.doc}` })),
    );
    const rows = el('div', { id: 'compose-allow' });
    const add = button('compose-add', 'Add', () => {
      const f = fields.find((x) => x.key === picker.value);
      if (f && !rows.querySelector(`[data-key="allow.${CSS.escape(f.key)}"]`)) rows.append(allowRow(f));
    });
    return el('fieldset', { className: 'compose-set' }, [
      el('legend', { textContent: 'Fields the student may change' }),
      el('div', { className: 'buttons' }, [
        el('label', { htmlFor: 'compose-field', textContent: 'Field' }),
        picker,
        add,
      ]),
      rows,
    ]);
  }

  function allowRow(f) {
    const row = el('div', { className: 'compose-row' });
    row.dataset.key = `allow.${f.key}`;
    row.dataset.field = f.key;
    const id = `compose-allow-${f.key}`;
    const remove = button(`${id}-remove`, 'Remove', () => row.remove());
    remove.setAttribute('aria-label', `Remove ${f.key}`);
    const unit = f.unit ? ` ${f.unit}` : '';
    if (f.options.length) {
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

  function needSet(measures) {
    const rows = el('div', { id: 'compose-need' });
    for (const fig of figures) {
      const m = measures?.figures.find((x) => x.name === fig.name);
      if (measures && !m) continue; // this scenario does not measure it (no step, no load step)
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

  function needRow(fig, m) {
    const id = `compose-need-${fig.name}`;
    const row = el('div', { className: 'compose-row' });
    row.dataset.key = `need.${fig.name}`;
    row.dataset.figure = fig.name;
    const unit = fig.unit ? ` ${fig.unit}` : '';
    const now = m ? ` — now ${m.value === Infinity ? '∞' : Number(m.value.toPrecision(4))}${unit}` : '';
    const band = fig.name === 'mean_nis';
    const op = el(
      'select',
      { id: `${id}-op`, name: 'op' },
      (band ? ['band', 'max', 'min'] : ['max', 'min', 'abs']).map((o) =>
        el('option', {
          value: o,
          textContent: { max: 'at most', min: 'at least', abs: '|value| at most', band: 'inside its 95 % band' }[o],
        }),
      ),
    );
    if (ABS.has(fig.name)) op.value = 'abs';
    const bound = el('input', { id: `${id}-bound`, name: 'bound', size: 8, inputMode: 'decimal' });
    if (m && Number.isFinite(m.value)) bound.value = round2((op.value === 'min' ? 1.2 : 0.8) * Math.abs(m.value));
    const syncBound = () => {
      bound.disabled = op.value === 'band';
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

  function varySet(info) {
    const vary = el('input', {
      id: 'compose-vary',
      size: 40,
      placeholder: 'seeds:2..10  or  model.j=0.016|model.j=0.024',
    });
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

  function fail(text, key = null) {
    error.textContent = text;
    error.hidden = !text;
    for (const r of box.querySelectorAll('[data-key]')) {
      const bad = r.dataset.key === key;
      r.classList.toggle('invalid', bad);
      for (const c of r.querySelectorAll('input, select')) c.toggleAttribute('aria-invalid', bad);
    }
  }

  /** The challenge text the form describes; `null` with a message when it lacks a part. */
  function compose() {
    const q = (id) => $(id).value.trim();
    const enc = encodeURIComponent;
    const parts = ['c=1', `title=${enc(q('compose-title'))}`, `base=${enc(base.encoded)}`];
    for (const row of $('compose-allow').children) {
      const v = (name) => row.querySelector(`[name=${name}]`).value.trim();
      parts.push(
        `allow.${row.dataset.field}=${row.querySelector('[name=options]') ? v('options').split('|').map(enc).join('|') : `${enc(v('lo'))}..${enc(v('hi'))}`}`,
      );
    }
    const robust = [];
    for (const row of $('compose-need').children) {
      if (!row.querySelector('[name=use]').checked) continue;
      const op = row.querySelector('[name=op]').value;
      const bound = row.querySelector('[name=bound]').value.trim();
      parts.push(`need.${row.dataset.figure}=${op === 'band' ? 'band' : `${op}:${enc(bound)}`}`);
      if (row.querySelector('[name=robust]').checked) robust.push(row.dataset.figure);
    }
    const vary = q('compose-vary');
    if (vary)
      parts.push(
        `vary=${
          vary.startsWith('seeds:')
            ? vary
            : vary
                .split('|')
                .map((v) => enc(v.trim()))
                .join('|')
        }`,
      );
    if (robust.length) parts.push(`robust=${robust.join(',')}`);
    return parts.join('&');
  }

  /** The key a core message is about: `allow.F`, `need.F`, `vary`, … (or a field named alone). */
  function keyOf(message) {
    const named = /'((?:allow|need)\.[^']+|vary|robust|title|base)'/.exec(message)?.[1];
    if (named) return named;
    const field = /field '([^']+)'/.exec(message)?.[1];
    if (field && box.querySelector(`[data-key="allow.${CSS.escape(field)}"]`)) return `allow.${field}`;
    if (field && box.querySelector(`[data-key="need.${CSS.escape(field)}"]`)) return `need.${field}`;
    return field ?? null;
  }

  async function make() {
    const text = compose();
    let desc;
    try {
      desc = await client.job('challenge', { text });
    } catch (e) {
      fail(`The challenge is not valid: ${e.message}`, keyOf(e.message));
      output.hidden = true;
      document.body.dataset.compose = 'invalid';
      return;
    }
    fail('');
    const url = `${location.origin}${location.pathname}?${desc.encoded}`;
    const linkBox = el('textarea', { id: 'compose-link', readOnly: true, rows: 3, value: url });
    const briefBox = el('textarea', { id: 'compose-brief', readOnly: true, rows: 12, value: desc.brief });
    const copied = el('p', { className: 'hint', role: 'status' });
    const copier = (id, label, what, text2) =>
      button(id, label, async () => {
        try {
          await navigator.clipboard.writeText(text2);
          copied.textContent = `${what} copied.`;
        } catch {
          copied.textContent = `Select the ${what.toLowerCase()} above and copy it.`;
        }
      });
    output.replaceChildren(
      el('label', { htmlFor: 'compose-link', textContent: 'Challenge link' }),
      linkBox,
      el('div', { className: 'buttons' }, [
        copier('compose-copy-link', 'Copy challenge link', 'The challenge link', url),
        el('a', {
          href: `?${desc.encoded}`,
          id: 'compose-open',
          textContent: 'Open as a student',
          target: '_blank',
          rel: 'noopener',
        }),
      ]),
      el('label', { htmlFor: 'compose-brief', textContent: 'The task in words (for a slide or the course page)' }),
      briefBox,
      el('div', { className: 'buttons' }, [copier('compose-copy-brief', 'Copy the task', 'The task', desc.brief)]),
      copied,
    );
    output.hidden = false;
    document.body.dataset.compose = 'made';
  }

  let filled = false;
  $('compose-fill').addEventListener('click', fill);
  $('tab-challenge').addEventListener('click', () => {
    if (!filled && state.info) {
      filled = true;
      fill();
    }
  });
}
