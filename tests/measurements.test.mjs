// The lessons' numbers are measurements: the table (web/teaching/measurements/*.csv) is measured
// again by the core and must not differ; each lesson's texts name only measurements of its own
// table, hold no number that is neither a measurement nor a setting they name, and every
// conclusion their words state holds on the table.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { LESSONS } from '../web/teaching/teaching.js';
import { lessonsIn } from './texts.mjs';
import { FluentResource } from '@fluent/bundle';
import {
  LESSON_TEXTS,
  namedIn,
  parseTables,
  placeholdersOf,
  render,
  withoutPlaceholders,
} from '../web/teaching/measured.js';
import { numbersIn } from './claims.mjs';
import { SECTIONS, STABILITY_CAUSES, WALKTHROUGH_GIVENS, WALKTHROUGH_HOLDS } from '../web/teaching/walkthrough-text.js';
import { declarations, markedIn, measuredDocs, prose, renderDoc } from '../scripts/measured-docs.mjs';

const CLI = new URL('../target/release/imlab', import.meta.url).pathname;
const DIR = new URL('../web/teaching/measurements/', import.meta.url).pathname;
const FILES = readdirSync(DIR)
  .filter((f) => f.endsWith('.csv'))
  .sort();
const tableOf = (file) => parseTables([readFileSync(DIR + file, 'utf8')]);
const TABLE = parseTables(FILES.map((f) => readFileSync(DIR + f, 'utf8')));
// The guides' tables (docs/measured/NAME.csv, one a guide), measured in the same check.
const DOCS = measuredDocs();

// Settings a text names as `key = value`: the scenario's own fields, which the codec knows.
const FIELDS = new Set(
  execFileSync(CLI, ['describe', 'v=1&preset=step'])
    .toString()
    .split('\n')
    .map((l) => l.split(/\s+/)[0])
    .filter((k) => k && !k.startsWith('#')),
);
const SETTING = /\b([a-z][\w.]*) ?= ?(−?[\d.]+(?:e−?\d+)?)/g;
// Equation numbers of the paper: (26), (26)–(28).
const EQUATION = /\(\d+\)(?:–\(\d+\))?/g;

/**
 * The value of a condition over the table: `A op B`, each side a sum of products of ids and
 * numbers (with unary minus and parentheses), op one of == != < <= > >=.
 */
export function holds(condition, table) {
  const tokens = condition.match(/\s*([A-Za-z][\w.]*|\d+(?:\.\d+)?(?:e-?\d+)?|==|!=|<=|>=|[-+*/()<>])/g);
  assert.equal(tokens?.join(''), condition, `'${condition}': not a condition`);
  const list = tokens.map((t) => t.trim());
  let i = 0;
  const atom = () => {
    const t = list[i++];
    if (t === '-') return -atom();
    if (t === '(') {
      const v = sum();
      assert.equal(list[i++], ')', `'${condition}': unbalanced`);
      return v;
    }
    if (/^\d/.test(t)) return Number(t);
    assert.ok(table.has(t), `'${condition}': no measurement '${t}'`);
    return table.get(t).value;
  };
  const product = () => {
    let v = atom();
    while (list[i] === '*' || list[i] === '/') v = list[i++] === '*' ? v * atom() : v / atom();
    return v;
  };
  const sum = () => {
    let v = product();
    while (list[i] === '+' || list[i] === '-') v = list[i++] === '+' ? v + product() : v - product();
    return v;
  };
  const left = sum();
  const op = list[i++];
  const right = sum();
  assert.equal(i, list.length, `'${condition}': trailing words`);
  const result = { '==': left === right, '!=': left !== right, '<': left < right, '<=': left <= right }[op];
  return result ?? { '>': left > right, '>=': left >= right }[op];
}

/** The numbers of `text` outside its placeholders that no given, setting or equation covers. */
function untyped(text, givens) {
  let rest = withoutPlaceholders(text);
  for (const g of givens) rest = rest.replaceAll(g, '⟨given⟩');
  rest = rest.replace(SETTING, (all, key) => (FIELDS.has(key) ? '⟨setting⟩' : all)).replace(EQUATION, '⟨eq⟩');
  return numbersIn(rest);
}

/**
 * Every condition holds on the table, and every row of the table is named by the text or a
 * condition.
 */
function holdsAndUsesAll(own, named, conditions) {
  assert.deepEqual(
    conditions.filter((c) => !holds(c, own)),
    [],
    'conditions that do not hold on the table',
  );
  const used = (id) => named.has(id) || conditions.some((c) => c.match(/[A-Za-z][\w.]*/g).includes(id));
  assert.deepEqual(
    [...own.keys()].filter((id) => !used(id)),
    [],
    'measurements no text or condition uses',
  );
}

// What a guide may number besides its measurements: its references to the paper and to itself
// (Section 3.1, Theorem 4.6, Fig 3, lessons 4, 11 and 12, step 1, seeds 1 to 30) and its lists' numbers.
const REFERENCE =
  /\b(?:Sections?|Theorem|Fig\.?|Figure|[Ss]eeds?|[Ll]essons?|Eqs?\.?|[Ii]tems?|[Ss]teps?)\s+\d+(?:\.\d+)?(?:(?:,|–| and| or| to)\s*\d+(?:\.\d+)?)*/g;
const LIST_ITEM = /^(\s*)\d+\.(?= )/gm;
// A guide's figures past this comment are of the code's speed, each with its date, machine and
// command, and not measurements of a run.
const END = '<!--measured end-->';
/** The part of a guide whose numbers must be measurements. */
const measuredPart = (text) => (text.includes(END) ? text.slice(0, text.indexOf(END)) : text);
/** The typed numbers of a guide's prose. */
const untypedInDoc = (text, givens) =>
  untyped(prose(measuredPart(text)).replace(REFERENCE, '⟨ref⟩').replace(LIST_ITEM, '$1⟨n⟩'), givens);

test('the measurements table is what the core measures now', () => {
  // Each run once, on both cores; the message lists every row that differs.
  // A translated guide reads its English guide's table: each table once.
  const tables = [...new Set([...FILES.map((f) => DIR + f), ...DOCS.map((d) => d.table)])];
  execFileSync(CLI, ['claims', '--check', ...tables], { stdio: ['ignore', 'ignore', 'pipe'] });
});

test('the check fails on a table whose value differs', () => {
  // One row of the step's table, its value changed in its last bits: the check reads them all.
  const [header, first] = readFileSync(DIR + 'step-response.csv', 'utf8')
    .trim()
    .split('\n');
  const cells = first.split(',');
  cells[cells.length - 1] = String(Number(cells.at(-1)) * (1 + 1e-12));
  const changed = `/tmp/imlab-claims-${process.pid}.csv`;
  writeFileSync(changed, [header, cells.join(',')].join('\n'));
  assert.throws(
    () => execFileSync(CLI, ['claims', '--check', changed], { stdio: 'pipe' }),
    /1 of 1 measurements differ/,
  );
  writeFileSync(changed, [header, first].join('\n'));
  execFileSync(CLI, ['claims', '--check', changed], { stdio: 'pipe' });
});

/**
 * The English messages of `file` (web/locales/en/) whose ids are `ids`: each one's text with its
 * variables written back as the placeholders they name ({ $a-b--draws } as {a.b#draws}), or null
 * where the file has no such message.
 * @param {string} file
 * @param {string[]} ids
 */
function englishMessages(file, ids) {
  const resource = new FluentResource(readFileSync(new URL(`../web/locales/en/${file}`, import.meta.url), 'utf8'));
  const values = new Map(resource.body.map((m) => [m.id, m.value]));
  const text = (pattern) =>
    typeof pattern === 'string'
      ? pattern
      : pattern
          .map((p) => {
            if (typeof p === 'string') return p;
            if (p.type === 'var') return `{ $${p.name} }`;
            if (p.type === 'str') return p.value;
            throw new Error(`${file}: a measured text holds a ${p.type} expression`);
          })
          .join('');
  return ids.map((id) => (values.get(id) ? placeholdersOf(text(values.get(id))) : null));
}

// The walkthrough's measured texts: its sections' prose, notes and what their runs show, and the
// stability report's causes, each the id of its English message.
const WALKTHROUGH_IDS = [
  ...SECTIONS.flatMap((s) => [...s.prose, ...(s.note ? [s.note] : []), ...(s.shows ?? [])]),
  ...Object.values(STABILITY_CAUSES),
];
const WALKTHROUGH_TEXTS = englishMessages('walkthrough.ftl', WALKTHROUGH_IDS);

/**
 * Every measured text: its name, its table's file, the strings a reader reads, the conditions its
 * words state and the settings it names. A lesson's table is `ID.csv`.
 */
export const MEASURED = [
  ...lessonsIn('en').map((lesson) => ({
    name: `lesson ${lesson.id}`,
    file: `${lesson.id}.csv`,
    texts: LESSON_TEXTS.map((k) => lesson[k]),
    holds: lesson.holds ?? [],
    givens: lesson.givens ?? [],
  })),
  {
    name: 'walkthrough',
    file: 'walkthrough.csv',
    texts: WALKTHROUGH_TEXTS.map((text) => text ?? ''),
    missing: WALKTHROUGH_IDS.filter((_, i) => WALKTHROUGH_TEXTS[i] === null),
    holds: WALKTHROUGH_HOLDS,
    givens: WALKTHROUGH_GIVENS,
  },
];

for (const { name, file, texts, missing = [], holds: conditions, givens } of MEASURED) {
  test(`${name}: numbers from its table, conclusions that hold`, () => {
    assert.ok(FILES.includes(file), `no table ${file}`);
    assert.deepEqual(missing, [], 'texts without an English message');
    const own = tableOf(file);
    const named = new Set(texts.flatMap(namedIn));
    for (const id of named) assert.ok(own.has(id), `${id}: not in ${file}`);
    for (const text of texts) render(text, own);
    holdsAndUsesAll(own, named, conditions);
    for (const g of givens)
      assert.ok(
        texts.some((t) => t.includes(g)),
        `given '${g}' is not in the text`,
      );
    assert.deepEqual(
      texts.flatMap((t) => untyped(t, givens)),
      [],
      'numbers typed into the text: make each a measurement or name it as a given setting',
    );
  });
}

for (const { name, doc, table } of DOCS) {
  test(`docs/${name}.md: numbers from its table, conclusions that hold`, () => {
    const text = readFileSync(doc, 'utf8');
    const own = parseTables([readFileSync(table, 'utf8')]);
    const { holds: conditions, givens } = declarations(text);
    const named = new Set(markedIn(text));
    for (const id of named) assert.ok(own.has(id), `${id}: not in ${table}`);
    assert.ok(
      renderDoc(text, own) === text,
      `its numbers differ from the table: node scripts/measured-docs.mjs --write`,
    );
    holdsAndUsesAll(own, named, conditions);
    const read = prose(measuredPart(text));
    for (const g of givens) assert.ok(read.includes(g), `given '${g}' is not in the prose`);
    assert.deepEqual(
      untypedInDoc(text, givens),
      [],
      'numbers typed into the guide: mark each as a measurement or declare it a given',
    );
  });
}

test('a guide reads its marks, and a typed number in it fails', () => {
  const table = parseTables(['id,show,seeds,statistic,value\na.min,:2,1..30,min,6.619\nb,count,1..30,sum,3']);
  const text = 'From 1.2<!--a.min--> A, on <!--b--> of 30<!--b#draws--> draws (Section 3.1, step 2).\n';
  assert.equal(
    renderDoc(text, table),
    'From 6.6<!--a.min--> A, on 3<!--b--> of 30<!--b#draws--> draws (Section 3.1, step 2).\n',
  );
  assert.deepEqual(markedIn(text), ['a.min', 'b', 'b']);
  assert.deepEqual(untypedInDoc(renderDoc(text, table), []), []);
  assert.deepEqual(untypedInDoc('It needs 6.6 A; `imlab metrics step` prints 2.87.\n```\n7.1\n```\n', []), [
    '6.6',
    '2.87',
  ]);
  assert.deepEqual(untypedInDoc('1. It settles in 4.7 ms.', ['4.7 ms']), []);
  assert.deepEqual(declarations('<!--measured\nholds: a.min < 7\ngiven: 20 kHz\n-->'), {
    holds: ['a.min < 7'],
    givens: ['20 kHz'],
  });
});

test('a number typed into a lesson fails; a condition reads the table and can fail', () => {
  const lesson = LESSONS[0];
  assert.deepEqual(untyped('settles in 4.75 ms', lesson.givens), ['4.75']);
  assert.deepEqual(untyped('with k1 = 600 it settles', lesson.givens), []);
  assert.deepEqual(untyped('with speed = 600 it settles', lesson.givens), ['600']);
  const table = parseTables(['id,show,seeds,statistic,value\na.min,:2,1..30,min,2\nb,:2,1..30,max,3']);
  assert.equal(holds('a.min < b', table), true);
  assert.equal(holds('a.min > 1.5 * b', table), false);
  assert.equal(holds('b - a.min == 1', table), true);
  assert.equal(holds('-(a.min) * 2 >= -3', table), false);
  // A condition that names no measurement of its table is a constant, true whatever the run.
  for (const { name, file, holds: conditions } of MEASURED) {
    const own = tableOf(file);
    for (const c of conditions)
      assert.ok(
        c.match(/[A-Za-z][\w.]*/g).some((id) => own.has(id)),
        `${name}: '${c}' names no measurement of ${file}`,
      );
  }
});

test('the page renders a measurement with its digits and unit, a range rounded outward', () => {
  const table = parseTables([
    'id,show,seeds,statistic,value\na,ms:3,1..30,min,0.004650000000000001\nb,:2,1..30,mean,-25.43\nc,count,1..30,sum,7\nd,:2,1..30,mean,163000\ne,:2,1..30,max,1.947\nf,:2,1..30,min,1.947\ng,:2,1..30,min,-5.48\nh,:3,1..30,max,0.0123',
  ]);
  assert.equal(
    render('{a} ms, {b}, {c} of {c#draws}, {d}, {e}, {f}, {g}, {h}', table),
    '4.65 ms, −25, 7 of 30, 160,000, 2.0, 1.9, −5.5, 0.0123',
  );
  assert.throws(() => render('{z}', table), /no measurement 'z'/);
});

test('every table belongs to a measured text', () => {
  for (const d of DOCS) assert.ok(existsSync(d.doc), `docs/measured/${d.name}.csv: no docs/${d.name}.md`);
  const ids = new Set(MEASURED.map((t) => t.file));
  assert.deepEqual(
    FILES.filter((f) => !ids.has(f)),
    [],
  );
  assert.ok(TABLE.size > 0);
});

// "Settled" means settled: every final value `imlab metrics` calls settled, on every preset and
// every lesson's run, stays within its tolerance in a run four times longer (at most 20 s, the
// longest run accepted), on seeds 1–10. One table of measurements, each run once on both cores.
const FINALS = ['speed_error_final', 'speed_estimate_error_final', 'flux_error_final'];
const LONGEST = 20;
/** `run` with its duration multiplied by `k` (at most LONGEST s). */
function longer(run, k) {
  const duration = Number(
    execFileSync(CLI, ['describe', run])
      .toString()
      .match(/^duration\s+=\s+(\S+)/m)[1],
  );
  const d = Math.min(LONGEST, k * duration);
  return /(^|&)duration=/.test(run) ? run.replace(/duration=[^&]*/, `duration=${d}`) : `${run}&duration=${d}`;
}

test('a final value called settled stays within its tolerance in a run four times longer', () => {
  const presets = execFileSync(CLI, ['list'])
    .toString()
    .trim()
    .split('\n')
    .map((l) => `v=1&preset=${l.split(/\s+/)[0]}`);
  const runs = [...new Set([...presets, ...LESSONS.map((l) => l.run)])];
  const rows = ['id,scenario,figure,seeds,statistic,show,value'];
  const seeds = Array.from({ length: 10 }, (_, i) => i + 1);
  runs.forEach((run, r) => {
    for (const seed of seeds)
      FINALS.forEach((f, k) => {
        const id = `r${r}.s${seed}.f${k}`;
        rows.push(`${id}.settled,${run}&seed=${seed},${f}_settled,-,max,count,`);
        rows.push(`${id}.value,${run}&seed=${seed},${f},-,max,:3,`);
        rows.push(`${id}.longer,${longer(run, 4)}&seed=${seed},${f},-,max,:3,`);
        rows.push(`${id}.tolerance,${run}&seed=${seed},${f}_tolerance,-,max,:3,`);
      });
  });
  const file = `/tmp/imlab-settled-${process.pid}.csv`;
  writeFileSync(file, rows.join('\n'));
  const table = parseTables([execFileSync(CLI, ['claims', file], { stdio: ['ignore', 'pipe', 'pipe'] }).toString()]);
  const wrong = [];
  let settled = 0;
  runs.forEach((run, r) => {
    for (const seed of seeds)
      FINALS.forEach((f, k) => {
        const v = (what) => table.get(`r${r}.s${seed}.f${k}.${what}`).value;
        if (v('settled') !== 1) return;
        settled++;
        // The tolerance the core judged the value settled within.
        if (!(Math.abs(v('longer') - v('value')) <= v('tolerance')))
          wrong.push(`${run}&seed=${seed} ${f}: ${v('value')} settled, ${v('longer')} in ${longer(run, 4)}`);
      });
  });
  assert.ok(settled > 0);
  assert.deepEqual(wrong, []);
});
