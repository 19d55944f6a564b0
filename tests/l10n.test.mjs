// The translations: every English message in every language, with its variables and no number of
// its own, the glossary followed, every message the page names present, and every lesson rendered
// in every language from the one table of measurements.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import { FluentBundle, FluentResource } from '@fluent/bundle';
import { LANGS, messages, problems, quotedLabels } from '../scripts/l10n-lint.mjs';
import { LANGUAGES } from '../web/l10n/languages.js';
import { LESSONS } from '../web/teaching/teaching.js';
import { LESSON_TEXTS, measuredArgs, parseTables } from '../web/teaching/measured.js';

const LOCALES = new URL('../web/locales/', import.meta.url).pathname;
const FILES = readdirSync(`${LOCALES}en`).filter((f) => f.endsWith('.ftl'));
const TABLES = new URL('../web/teaching/measurements/', import.meta.url).pathname;
const TABLE = parseTables(
  readdirSync(TABLES)
    .filter((f) => f.endsWith('.csv'))
    .map((f) => readFileSync(TABLES + f, 'utf8')),
);

test('the page offers the languages the checks cover', () => {
  assert.deepEqual(
    LANGUAGES.map(([code]) => code),
    ['en', ...LANGS],
  );
  assert.deepEqual(readdirSync(LOCALES).sort(), ['en', ...LANGS].sort());
  // The guides' pages name the same languages.
  const docs = readFileSync(new URL('../scripts/docs_html.py', import.meta.url), 'utf8');
  assert.deepEqual(
    [...docs.match(/LANGUAGES = \{(.*)\}/)[1].matchAll(/"([^"]+)": "([^"]+)"/g)].map((m) => [m[1], m[2]]),
    LANGUAGES.filter(([code]) => code !== 'en'),
  );
});

for (const lang of LANGS)
  test(`${lang}: every English message, with its variables, no number of its own, the glossary’s words, the labels as the page says them`, () => {
    assert.deepEqual([...FILES.flatMap((f) => problems(lang, f)), ...quotedLabels(lang)], []);
  });

test('the checks fail on a missing message, a lost variable, a typed number and a glossary slip', () => {
  const en = 'a = Settles in { $s-min } ms with the observer.\nb = Two words.\n';
  const tr = 'a = Setzt sich in 4 ms mit dem Schätzer.\n';
  assert.deepEqual(
    problems('xx', 'f.ftl', { en, tr, glossary: [{ en: 'observer', term: 'Beobachter', avoid: ['Schätzer'] }] }),
    [
      'xx/f.ftl: b is not translated',
      'xx/f.ftl: a has variables , the English s-min',
      'xx/f.ftl: a states 4, which the English does not',
      'xx/f.ftl: a says “observer” in English but not “Beobachter”',
      'xx/f.ftl: a says “Schätzer”, not “Beobachter”',
    ],
  );
});

test('every message the page names is an English message', () => {
  // A message with attributes only is named by its id, each attribute by `id.attribute`.
  const ids = new Set(
    FILES.flatMap((f) => [...messages(readFileSync(`${LOCALES}en/${f}`, 'utf8')).keys()]).flatMap((id) => [
      id,
      id.split('.')[0],
    ]),
  );
  const named = [];
  const walk = (dir) => {
    for (const e of readdirSync(dir, { withFileTypes: true })) {
      const path = `${dir}/${e.name}`;
      if (e.isDirectory()) walk(path);
      else if (e.name.endsWith('.js'))
        for (const m of readFileSync(path, 'utf8').matchAll(/\bt\('([a-z0-9-]+(?:\.[a-z-]+)?)'/g))
          named.push([path, m[1]]);
    }
  };
  walk(new URL('../web', import.meta.url).pathname);
  for (const m of readFileSync(new URL('../static/index.html', import.meta.url), 'utf8').matchAll(
    /data-l10n-id="([^"]+)"/g,
  ))
    named.push(['index.html', m[1]]);
  assert.ok(named.length > 20, `only ${named.length} messages named: the scan is broken`);
  assert.deepEqual(
    named.filter(([, id]) => !ids.has(id)).map(([path, id]) => `${path}: ${id}`),
    [],
  );
});

for (const [lang] of LANGUAGES)
  test(`${lang}: every lesson renders with the table's numbers, shown in the language`, () => {
    const bundle = new FluentBundle(lang, { useIsolating: false });
    const text = readFileSync(`${LOCALES}${lang}/lessons.ftl`, 'utf8');
    assert.deepEqual(bundle.addResource(new FluentResource(text)), []);
    const args = measuredArgs(TABLE, lang);
    for (const lesson of LESSONS)
      for (const k of LESSON_TEXTS) {
        const message = bundle.getMessage(`${lesson.id}-${k}`);
        assert.ok(message?.value, `${lang}: ${lesson.id}-${k} is missing`);
        const errors = [];
        const shown = bundle.formatPattern(message.value, args, errors);
        assert.deepEqual(errors.map(String), [], `${lang}: ${lesson.id}-${k}`);
        assert.ok(shown.trim() !== '', `${lang}: ${lesson.id}-${k} is empty`);
      }
  });

test('a measured number is the same number in every language, with the language’s separators', () => {
  const table = parseTables(['id,show,seeds,statistic,value\na.max,ms:3,1..30,max,0.0046499\nb,:6,-,mean,-12345.6']);
  const shown = Object.fromEntries(['en', 'de', 'fr', 'ja'].map((l) => [l, measuredArgs(table, l)]));
  assert.deepEqual(
    Object.values(shown).map((a) => [a['a-max'], a['a-max--draws'], a.b]),
    [
      ['4.65', 30, '−12,345.6'],
      ['4,65', 30, '−12.345,6'],
      ['4,65', 30, '−12\u202f345,6'],
      ['4.65', 30, '−12,345.6'],
    ],
  );
});
