// The walkthrough's inspect panel: every term of the design at one sample, by step, with its
// value, unit and meaning, and the Kalman gain; exact values in tooltips and in the copied text.
// Its words are the page's messages (teaching-page.ftl): a sample is inspected from the first plot
// on. The terms' meanings and units are the core's.
import { six } from '../plots/plots.js';
import { el } from '../ui/dom.js';
import { t } from '../l10n/l10n.js';
import { decimal } from './walkthrough-sections.js';
import { plain, tex } from './tex.js';

/**
 * A sample as the core gives it: its k, its columns with their values and docs, the Kalman gain
 * and L, a row a state.
 * @typedef {import('../worker/protocol.js').Inspected['snapshot']} Snapshot
 */

// Terms of the inspect panel, grouped by step: each group's caption (a message and its variables)
// and its terms, [column, TeX label].
/** @type {[[string, Record<string, number>?], [string, string][]][]} */
const INSPECT = [
  [
    ['inspect-group-step', { step: 1 }],
    [
      ['z1', 'z_1'],
      ['v1', 'v_1'],
      ['v1a', 'v_{1a}'],
      ['v1s', 'v_{1s}'],
      ['torque_hat', 'a_1(x_3\\hat x_4 - x_2\\hat x_5)'],
    ],
  ],
  [
    ['inspect-group-step', { step: 2 }],
    [
      ['z2', 'z_2'],
      ['v2', 'v_2'],
      ['v2a', 'v_{2a}'],
      ['v2s', 'v_{2s}'],
      ['psi2', '\\psi_2'],
    ],
  ],
  [
    ['inspect-group-step', { step: 3 }],
    [
      ['z3', 'z_3'],
      ['v3', 'v_3'],
      ['v3a', 'v_{3a}'],
      ['v3s', 'v_{3s}'],
      ['psi3', '\\psi_3'],
    ],
  ],
  [
    ['inspect-group-step', { step: 4 }],
    [
      ['z4', 'z_4'],
      ['v4', 'v_4'],
      ['v4a', 'v_{4a}'],
      ['v4s', 'v_{4s}'],
      ['psi4', '\\psi_4'],
    ],
  ],
  [
    ['inspect-group-voltage'],
    [
      ['u_a_cmd', 'u_1\\ \\text{before}'],
      ['u_b_cmd', 'u_2\\ \\text{before}'],
      ['u_a', 'u_1\\ \\text{applied}'],
      ['u_b', 'u_2\\ \\text{applied}'],
      ['lyapunov', 'V'],
    ],
  ],
  [
    ['inspect-group-estimate'],
    [
      ['omega_hat', '\\hat x_1'],
      ['i_sa_hat', '\\hat x_2'],
      ['i_sb_hat', '\\hat x_3'],
      ['phi_ra_hat', '\\hat x_4'],
      ['phi_rb_hat', '\\hat x_5'],
    ],
  ],
  [
    ['inspect-group-measured'],
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
  const close = el('button', { type: 'button', className: 'close', textContent: t('inspect-close') });
  close.setAttribute('aria-keyshortcuts', 'Escape');
  close.addEventListener('click', onClose);
  const copy = el('button', { type: 'button', className: 'copy', textContent: t('inspect-copy') });
  const lines = snap.columns.map((/** @type {string} */ c) => `${c}\t${exact(value[c])}\t${doc[c][1]}`);
  copy.addEventListener('click', async () => {
    const text = [`k\t${snap.k}`, ...lines].join('\n');
    try {
      await navigator.clipboard.writeText(text);
      copy.textContent = t('inspect-copied');
    } catch {
      copy.textContent = t('inspect-copy-failed');
    }
  });
  const title = el('h2', {
    id: 'inspect-title',
    textContent: t('inspect-title', { k: String(snap.k), time: decimal(time) }),
  });
  return el('div', { className: 'inspect-head' }, [title, copy, close]);
}

/**
 * A table's row of column headers `names`.
 * @param {string[]} names
 */
const headRow = (names) =>
  el(
    'tr',
    {},
    names.map((h) => el('th', { scope: 'col', textContent: h })),
  );

/**
 * The tooltip of value `v`: its exact value.
 * @param {number} v
 */
const exactTitle = (v) => t('inspect-exact', { value: exact(v) });

/**
 * One table a group of INSPECT: each term's value (6 significant digits), unit and meaning.
 * @param {Record<string, number>} value
 * @param {Record<string, [string, string]>} doc
 */
function termTables(value, doc) {
  const head = [t('inspect-term'), t('inspect-value'), t('inspect-unit'), t('inspect-meaning')];
  return INSPECT.map(([[title, args], terms]) => {
    const table = el('table', {}, [el('caption', { textContent: t(title, args) }), headRow(head)]);
    for (const [col, label] of terms) {
      const [meaning, unit] = doc[col];
      const cell = el('td', { textContent: six(value[col]), title: exactTitle(value[col]) });
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
    el('caption', { textContent: t('inspect-gain-caption') }),
    headRow([t('inspect-gain-row'), 'K·1', 'K·2', 'L·1', 'L·2']),
  ]);
  snap.gain.forEach((/** @type {number[]} */ row, /** @type {number} */ i) => {
    gain.append(
      el('tr', {}, [
        el('th', { scope: 'row' }, [tex(`K_{${i + 1}\\cdot}`, false, `K${i + 1}·`)]),
        ...row.map((v) => el('td', { textContent: six(v), title: exactTitle(v) })),
        ...snap.l[i].map((/** @type {number} */ v) => el('td', { textContent: six(v), title: exactTitle(v) })),
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
