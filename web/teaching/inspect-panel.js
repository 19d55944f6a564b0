// The walkthrough's inspect panel: every term of the design at one sample, by step, with its
// value, unit and meaning, and the Kalman gain; exact values in tooltips and in the copied text.
import { six } from '../plots/plots.js';
import { el } from '../ui/dom.js';
import { plain, tex } from './tex.js';

/**
 * A sample as the core gives it: its k, its columns with their values and docs, the Kalman gain
 * and L, a row a state.
 * @typedef {import('../worker/protocol.js').Inspected['snapshot']} Snapshot
 */

// Terms of the inspect panel, grouped by step: [column, TeX label].
/** @type {[string, [string, string][]][]} */
const INSPECT = [
  [
    'Step 1',
    [
      ['z1', 'z_1'],
      ['v1', 'v_1'],
      ['v1a', 'v_{1a}'],
      ['v1s', 'v_{1s}'],
      ['torque_hat', 'a_1(x_3\\hat x_4 - x_2\\hat x_5)'],
    ],
  ],
  [
    'Step 2',
    [
      ['z2', 'z_2'],
      ['v2', 'v_2'],
      ['v2a', 'v_{2a}'],
      ['v2s', 'v_{2s}'],
      ['psi2', '\\psi_2'],
    ],
  ],
  [
    'Step 3',
    [
      ['z3', 'z_3'],
      ['v3', 'v_3'],
      ['v3a', 'v_{3a}'],
      ['v3s', 'v_{3s}'],
      ['psi3', '\\psi_3'],
    ],
  ],
  [
    'Step 4',
    [
      ['z4', 'z_4'],
      ['v4', 'v_4'],
      ['v4a', 'v_{4a}'],
      ['v4s', 'v_{4s}'],
      ['psi4', '\\psi_4'],
    ],
  ],
  [
    'Voltage (54) and limit',
    [
      ['u_a_cmd', 'u_1\\ \\text{before}'],
      ['u_b_cmd', 'u_2\\ \\text{before}'],
      ['u_a', 'u_1\\ \\text{applied}'],
      ['u_b', 'u_2\\ \\text{applied}'],
      ['lyapunov', 'V'],
    ],
  ],
  [
    'Estimate x̂ (k|k)',
    [
      ['omega_hat', '\\hat x_1'],
      ['i_sa_hat', '\\hat x_2'],
      ['i_sb_hat', '\\hat x_3'],
      ['phi_ra_hat', '\\hat x_4'],
      ['phi_rb_hat', '\\hat x_5'],
    ],
  ],
  [
    'Measured and true',
    [
      ['y_a', 'y_1'],
      ['y_b', 'y_2'],
      ['omega', 'x_1'],
      ['omega_ref', '\\omega_d'],
    ],
  ],
];

/**
 * Shortest text that reads back as the same double (as the CLI's CSV writes it).
 * @param {number} v
 */
const exact = (v) => String(v);

/** The panel's heading: the sample's k and t (`ts`, the sampling period, rounds t to its
 * sample), the copy button and the close button, which calls `onClose`.
 * @param {Snapshot} snap
 * @param {Record<string, number>} value
 * @param {Record<string, [string, string]>} doc
 * @param {number} ts
 * @param {() => void} onClose
 */
function panelHead(snap, value, doc, ts, onClose) {
  const digits = Math.max(0, -Math.floor(Math.log10(ts)) + 1);
  const time = value.t.toFixed(digits).replace(/0+$/, '').replace(/\.$/, '');
  const close = el('button', { type: 'button', className: 'close', textContent: 'Close (Esc)' });
  close.setAttribute('aria-keyshortcuts', 'Escape');
  close.addEventListener('click', onClose);
  const copy = el('button', { type: 'button', className: 'copy', textContent: 'Copy exact values' });
  const lines = snap.columns.map((/** @type {string} */ c) => `${c}\t${exact(value[c])}\t${doc[c][1]}`);
  copy.addEventListener('click', async () => {
    const text = [`k\t${snap.k}`, ...lines].join('\n');
    try {
      await navigator.clipboard.writeText(text);
      copy.textContent = 'Copied';
    } catch {
      copy.textContent = 'Copy failed: select the table instead';
    }
  });
  const title = el('h2', { id: 'inspect-title', textContent: `Inspect sample k = ${snap.k}, t = ${time} s` });
  return el('div', { className: 'inspect-head' }, [title, copy, close]);
}

/**
 * A table of columns `names`, each a column header.
 * @param {string[]} names
 */
const headRow = (names) =>
  el(
    'tr',
    {},
    names.map((h) => el('th', { scope: 'col', textContent: h })),
  );

/**
 * One table a group of INSPECT: each term's value (6 significant digits), unit and meaning.
 * @param {Record<string, number>} value
 * @param {Record<string, [string, string]>} doc
 */
function termTables(value, doc) {
  return INSPECT.map(([title, terms]) => {
    const table = el('table', {}, [
      el('caption', { textContent: title }),
      headRow(['term', 'value', 'unit', 'meaning']),
    ]);
    for (const [col, label] of terms) {
      const [meaning, unit] = doc[col];
      const cell = el('td', { textContent: six(value[col]), title: `exact: ${exact(value[col])}` });
      cell.dataset.exact = exact(value[col]);
      const row = el('tr', {}, [
        el('th', { scope: 'row' }, [tex(label, false, plain(label))]),
        cell,
        el('td', { className: 'unit', textContent: unit }),
        el('td', { className: 'doc', textContent: meaning }),
      ]);
      row.dataset.column = col;
      table.append(row);
    }
    return table;
  });
}

/**
 * The Kalman gain K_k and L = K_k/Ts, a row a state.
 * @param {Snapshot} snap
 */
function gainTable(snap) {
  const gain = el('table', {}, [
    el('caption', { textContent: 'Kalman gain K_k (A⁻¹ × state unit) and L = K_k/Ts (per second)' }),
    headRow(['row', 'K·1', 'K·2', 'L·1', 'L·2']),
  ]);
  snap.gain.forEach((/** @type {number[]} */ row, /** @type {number} */ i) => {
    gain.append(
      el('tr', {}, [
        el('th', { scope: 'row' }, [tex(`K_{${i + 1}\\cdot}`, false, `K${i + 1}·`)]),
        ...row.map((v) => el('td', { textContent: six(v), title: `exact: ${exact(v)}` })),
        ...snap.l[i].map((/** @type {number} */ v) => el('td', { textContent: six(v), title: `exact: ${exact(v)}` })),
      ]),
    );
  });
  return gain;
}

/**
 * Fills `box` with the sample `snap` (the core's terms, their docs and the gain); `ts` is the
 * sampling period (s) and `onClose` closes the panel. Returns the sample's time.
 * @param {HTMLElement} box
 * @param {Snapshot} snap
 * @param {number} ts
 * @param {() => void} onClose
 */
export function fillInspect(box, snap, ts, onClose) {
  /** @type {Record<string, number>} */
  const value = Object.fromEntries(
    snap.columns.map((/** @type {string} */ c, /** @type {number} */ i) => [c, snap.values[i]]),
  );
  /** @type {Record<string, [string, string]>} */
  const doc = Object.fromEntries(
    snap.columns.map((/** @type {string} */ c, /** @type {number} */ i) => [c, [snap.meanings[i], snap.units[i]]]),
  );
  box.replaceChildren(panelHead(snap, value, doc, ts, onClose));
  box.dataset.t = String(value.t);
  box.append(el('div', { className: 'inspect-grid' }, [...termTables(value, doc), gainTable(snap)]));
  return value.t;
}
