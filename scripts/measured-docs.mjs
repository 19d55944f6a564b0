// The guides' numbers are measurements, as the lessons' are. A guide `docs/NAME.md` with a table
// `docs/measured/NAME.csv` writes each number about a run followed by the row it shows, in an
// HTML comment that Markdown does not render: `6.61<!--s.i50.min-->`, or `30<!--s.i50.min#draws-->`
// for the number of noise draws a row's sample takes. The conditions its words state and the
// settings it names sit in one comment of their own:
//
//   <!--measured
//   holds: s.runaway.n == 0
//   given: 20 kHz
//   -->
//
// `node scripts/measured-docs.mjs --write` writes each marked number from the table (after
// `imlab claims --write docs/measured/NAME.csv`); without `--write` it lists the numbers that
// differ and exits with 1. tests/measurements.test.mjs checks the same, and that no other digit of
// a guide's prose is a typed measurement.
import { existsSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { parseTables, render } from '../web/teaching/measured.js';
import { LANGS } from './l10n-lint.mjs';

const DOCS = new URL('../docs/', import.meta.url).pathname;
export const TABLES = `${DOCS}measured/`;

/** A marked number: the number as written (possibly none yet), then its row. */
export const MARKED = /([−-]?(?:\d{1,3}(?:,\d{3})+|\d+)(?:\.\d+)?)?<!--([A-Za-z0-9._]+(?:#draws)?)-->/g;
const DECLARATIONS = /<!--measured\n([\s\S]*?)-->/;

/**
 * Every measured guide, its translations (`docs/LANG/NAME.md`, read against the same table) after
 * the English: its name (`NAME` or `LANG/NAME`), its Markdown's path, its table's path.
 * @returns {{ name: string, doc: string, table: string }[]}
 */
export function measuredDocs() {
  const english = readdirSync(TABLES)
    .filter((f) => f.endsWith('.csv'))
    .sort()
    .map((f) => ({ name: f.slice(0, -4), doc: `${DOCS}${f.slice(0, -4)}.md`, table: TABLES + f }));
  const translated = readdirSync(DOCS, { withFileTypes: true })
    .filter((d) => d.isDirectory() && LANGS.includes(d.name))
    .flatMap((d) =>
      english
        .filter((g) => existsSync(`${DOCS}${d.name}/${g.name}.md`))
        .map((g) => ({ ...g, name: `${d.name}/${g.name}`, doc: `${DOCS}${d.name}/${g.name}.md` })),
    );
  return [...english, ...translated];
}

/**
 * The conditions (`holds:`) and settings (`given:`) a guide declares.
 * @param {string} text
 */
export function declarations(text) {
  const block = text.match(DECLARATIONS)?.[1] ?? '';
  const lines = block
    .split('\n')
    .map((l) => l.trim())
    .filter(Boolean);
  const of = (kind) => lines.filter((l) => l.startsWith(`${kind}:`)).map((l) => l.slice(kind.length + 1).trim());
  const unknown = lines.filter((l) => !/^(holds|given):/.test(l));
  if (unknown.length) throw new Error(`a measured block's line is neither 'holds:' nor 'given:': ${unknown[0]}`);
  return { holds: of('holds'), givens: of('given') };
}

/**
 * `text` with each marked number as its row renders it.
 * @param {string} text
 * @param {import('../web/teaching/measured.js').Table} table
 */
export const renderDoc = (text, table) =>
  text.replace(MARKED, (_, _n, id) => `${render(`{${id}}`, table)}<!--${id}-->`);

/** The ids a guide's markers name, without `#draws`. */
export const markedIn = (text) => [...text.matchAll(MARKED)].map((m) => m[2].replace(/#draws$/, ''));

/** What a guide's reader reads as prose: no code, no comments, no link targets. */
export const prose = (text) =>
  text
    .replace(/^[ \t]*```[\s\S]*?^[ \t]*```/gm, '')
    .replace(/`[^`\n]*`/g, '')
    .replace(MARKED, '⟨m⟩')
    .replace(/<!--[\s\S]*?-->/g, '')
    .replace(/\]\([^)]*\)/g, ']');

function main() {
  const write = process.argv.includes('--write');
  let stale = 0;
  for (const { name, doc, table } of measuredDocs()) {
    const text = readFileSync(doc, 'utf8');
    const rendered = renderDoc(text, parseTables([readFileSync(table, 'utf8')]));
    if (rendered === text) continue;
    if (write) writeFileSync(doc, rendered);
    else {
      stale++;
      console.error(`docs/${name}.md: its numbers differ from docs/measured/${name}.csv`);
    }
  }
  if (stale) process.exit(1);
}

if (import.meta.url === `file://${process.argv[1]}`) main();
