// Builds the served page in a dist/ folder that already holds the core (pkg-run/, pkg/) and the vendored
// libraries (vendor/): every file the page loads before its first plot is minified and named by its
// content's hash, so that a browser keeps it as long as it is unchanged (scripts/serve.mjs says so).
//
//   web/worker-HASH.js      the worker and the run core's glue, one module, and a chunk with the
//                           jobs and the tools core's glue, fetched on the first job
//   web/imlab_bg-HASH.wasm  the two builds of the core (dist/pkg-run/, dist/pkg/), each fetched
//                           and compiled while it streams by the worker
//   web/main-HASH.js        the page's modules and uPlot, one module; KaTeX in a chunk of its own,
//                           fetched when an equation is first shown (web/teaching/tex.js)
//   (index.html)            the script that starts the worker early (web/boot.js), minified and
//                           written into the page's head, with its hash in the page's
//                           Content-Security-Policy: it starts the worker one round trip sooner
//   locales/LANG/PART-HASH.ftl  each language's messages: the page part, and the rest
//                           (the English page part's words are written into index.html too)
//   style-HASH.css          uPlot's stylesheet and the page's (style.css, present.css), one file
//   index.html              static/index.html, pointing at the above
//   sw.js                   static/sw.js, with the list of files it fetches when it installs
//
//   node scripts/bundle.mjs DIST
import { createHash } from 'node:crypto';
import { cpSync, mkdirSync, readFileSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { basename, join, relative } from 'node:path';
import * as esbuild from 'esbuild';
import { FluentBundle, FluentResource } from '@fluent/bundle';

const dist = process.argv[2];
if (!dist) {
  console.error('bundle: give the dist folder to build into');
  process.exit(2);
}
const out = join(dist, 'web');
// The sources, staged where their relative imports of ../pkg and ../vendor resolve; kept for the
// Node tests of the worker's jobs (a dot folder: scripts/serve.mjs does not serve it).
const src = join(dist, '.src');

/** The first 40 bits of `bytes`' SHA-256 in base32, as esbuild names its outputs. */
function hashOf(bytes) {
  const digest = createHash('sha256').update(bytes).digest();
  const alphabet = 'ABCDEFGHIJKLMNOPQRSTUVWXYZ234567';
  let bits = 0n;
  for (let i = 0; i < 5; i++) bits = (bits << 8n) | BigInt(digest[i]);
  let name = '';
  for (let i = 7; i >= 0; i--) name += alphabet[Number((bits >> BigInt(5 * i)) & 31n)];
  return name;
}

/** An esbuild plugin that gives the module whose path ends with `suffix` the source `contents`. */
const replaced = (suffix, contents) => ({
  name: `replace ${suffix}`,
  setup(build) {
    build.onLoad({ filter: new RegExp(`${suffix.replaceAll('.', '\\.')}$`) }, () => ({ contents, loader: 'js' }));
  },
});

/** Builds `options` into web/ and returns the outputs' names (relative to web/) by entry point. */
async function build(options) {
  const result = await esbuild.build({
    bundle: true,
    minify: true,
    format: 'esm',
    outdir: out,
    entryNames: '[name]-[hash]',
    chunkNames: '[name]-[hash]',
    metafile: true,
    logLevel: 'warning',
    ...options,
  });
  const outputs = {};
  for (const [path, output] of Object.entries(result.metafile.outputs))
    if (output.entryPoint)
      outputs[basename(output.entryPoint)] = { name: relative(out, path), imports: output.imports };
  return outputs;
}

rmSync(out, { recursive: true, force: true });
rmSync(src, { recursive: true, force: true });
for (const old of readdirSync(dist)) if (/^style.*\.css(\.br|\.gz)?$/.test(old)) rmSync(join(dist, old));
mkdirSync(out, { recursive: true });
cpSync('web', src, { recursive: true, filter: (path) => !/(tsconfig\.json|\.d\.ts)$/.test(path) });

/** Copies the core's module in `dist/PKG/` into web/ under its hashed name; returns the name. */
function hashedWasm(pkg) {
  const wasm = readFileSync(join(dist, pkg, 'imlab_bg.wasm'));
  const name = `imlab_bg-${hashOf(wasm)}.wasm`;
  writeFileSync(join(out, name), wasm);
  return name;
}
const runWasm = hashedWasm('pkg-run');
const toolsWasm = hashedWasm('pkg');

// The worker with the run's core; its jobs and the tools' core glue in a chunk it imports on the
// first job.
const worker = (
  await build({
    entryPoints: [join(src, 'worker', 'worker.js')],
    splitting: true,
    plugins: [
      replaced(
        '/wasm-url.js',
        `export const WASM_URL = new URL('./${runWasm}', import.meta.url);\n` +
          `export const TOOLS_WASM_URL = new URL('./${toolsWasm}', import.meta.url);`,
      ),
    ],
  })
)['worker.js'];

// uPlot makes a number and a date formatter as its module is evaluated. The page uses neither
// (every chart writes its numbers as web/plots/numbers.js does), and a page's first formatter
// loads its locale's data on the page's thread while nothing is plotted yet (docs/figures.md):
// both are made when first used, which is never.
const UPLOT_PATH = join(dist, 'vendor', 'uPlot.esm.js');
const uplot = [
  [
    "const numFormatter = new Intl.NumberFormat(domEnv ? nav.language : 'en-US');\nconst fmtNum = val => numFormatter.format(val);",
    "let numFormatter;\nconst fmtNum = val => (numFormatter ??= new Intl.NumberFormat(domEnv ? nav.language : 'en-US')).format(val);",
  ],
  ['const localTz = new Intl.DateTimeFormat().resolvedOptions().timeZone;', 'let localTz;'],
  ['else if (tz == localTz)', 'else if (tz == (localTz ??= new Intl.DateTimeFormat().resolvedOptions().timeZone))'],
].reduce((text, [from, to]) => once(text, from, to), readFileSync(UPLOT_PATH, 'utf8'));

// The lessons' measurements: of each table as `imlab claims` wrote it, the columns the page reads
// (the scenarios and probes stay in the repository, for the core to measure them again).
const TABLES_DIR = join('web', 'teaching', 'measurements');
const PAGE_COLUMNS = ['id', 'show', 'seeds', 'statistic', 'value'];
const tables = readdirSync(TABLES_DIR)
  .filter((f) => f.endsWith('.csv'))
  .sort()
  .map((f) => {
    const rows = readFileSync(join(TABLES_DIR, f), 'utf8')
      .trim()
      .split('\n')
      .map((l) => l.split(','));
    const kept = PAGE_COLUMNS.map((c) => rows[0].indexOf(c));
    if (kept.includes(-1)) throw new Error(`bundle: ${f} lacks a column of ${PAGE_COLUMNS.join(', ')}`);
    return rows.map((cells) => kept.map((i) => cells[i]).join(',')).join('\n');
  });

// The page's messages (web/locales/LANG/*.ftl): of each language a page part (what the page says
// before its first plot: its frame, the settings' meanings, the run's figures and warnings, the
// refusals of a scenario and of its formulas) and the rest (the tools, the law editor, challenges,
// the lessons and the walkthrough), each one file named by its hash in locales/LANG/. The page part
// of the language shown is fetched as the page starts, beside the core; the rest once the first
// plot is drawn or when a part of the page that says it is first used. The English page part's
// words are also written into index.html (below).
const LOCALES = join('web', 'locales');
const PAGE = ['page.ftl', 'core-scenario.ftl', 'core-formula.ftl', 'core-run.ftl'];
/** The files of `lang`'s `part`: the page part's, or every other. */
const partOf = (/** @type {string} */ lang, /** @type {string} */ part) =>
  readdirSync(join(LOCALES, lang))
    .filter((n) => n.endsWith('.ftl') && PAGE.includes(n) === (part === 'page'))
    .sort();
/** @type {Record<string, Record<string, string>>} */
const localeFiles = {};
let enPage = '';
let enRest = '';
rmSync(join(dist, 'locales'), { recursive: true, force: true });
for (const lang of readdirSync(LOCALES).sort()) {
  localeFiles[lang] = {};
  for (const part of ['page', 'rest']) {
    // Comments are for translators: a line that starts with `#` is one, and is not sent.
    const text = partOf(lang, part)
      .map((n) => readFileSync(join(LOCALES, lang, n), 'utf8'))
      .join('\n')
      .split('\n')
      .filter((line) => !line.startsWith('#'))
      .join('\n');
    if (text === '') continue;
    if (lang === 'en' && part === 'page') enPage = text;
    if (lang === 'en' && part === 'rest') enRest = text;
    const name = `locales/${lang}/${part}-${hashOf(Buffer.from(text))}.ftl`;
    mkdirSync(join(dist, 'locales', lang), { recursive: true });
    writeFileSync(join(dist, name), text);
    localeFiles[lang][part] = name;
  }
}

const main = (
  await build({
    entryPoints: [join(src, 'main.js')],
    splitting: true,
    plugins: [
      replaced('/worker-url.js', `export const WORKER_URL = new URL('./${worker.name}', import.meta.url);`),
      replaced('/vendor/uPlot.esm.js', uplot),
      replaced('/teaching/measurements.js', `export const TABLES = ${JSON.stringify(tables)};`),
      replaced('/l10n/catalog.js', `export const FILES = ${JSON.stringify(localeFiles)};`),
    ],
  })
)['main.js'];

const boot = (
  await esbuild.build({ entryPoints: [join(src, 'boot.js')], minify: true, write: false, logLevel: 'warning' })
).outputFiles[0].text.trim();

const style = await esbuild.build({
  stdin: {
    contents:
      '@import "./node_modules/uplot/dist/uPlot.min.css";\n@import "./static/style.css";\n@import "./static/present.css";\n',
    loader: 'css',
    resolveDir: '.',
  },
  bundle: true,
  minify: true,
  write: false,
  logLevel: 'warning',
});
const css = style.outputFiles[0].contents;
const styleName = `style-${hashOf(css)}.css`;
writeFileSync(join(dist, styleName), css);

/** `text` with `from` replaced by `to`, where `from` must occur exactly once. */
function once(text, from, to) {
  const at = text.indexOf(from);
  if (at < 0 || text.indexOf(from, at + 1) >= 0) throw new Error(`bundle: the source must hold "${from}" once`);
  return text.slice(0, at) + to + text.slice(at + from.length);
}
// The bundle's static imports (shared chunks) are fetched with it, not after it has been read.
const preloads = main.imports
  .filter((i) => i.kind === 'import-statement')
  .map((i) => `\n  <link rel="modulepreload" href="web/${relative(out, i.path)}">`)
  .join('');
let html = readFileSync('static/index.html', 'utf8');
html = once(
  html,
  '<script async src="web/boot.js" data-worker="web/worker/worker.js"></script>',
  `<script data-worker="web/${worker.name}">${boot}</script>`,
);
html = once(
  html,
  "script-src 'self'",
  `script-src 'self' 'sha256-${createHash('sha256').update(boot).digest('base64')}'`,
);
html = once(
  html,
  '<link rel="stylesheet" href="vendor/uPlot.min.css">\n  <link rel="stylesheet" href="style.css">\n  <link rel="stylesheet" href="present.css">',
  `<link rel="stylesheet" href="${styleName}">`,
);
html = once(
  html,
  '<script type="module" src="web/main.js"></script>',
  `<script type="module" src="web/${main.name}"></script>${preloads}`,
);
// The page's own words are its English messages, of both parts (the Analysis, Lessons and Challenge
// tabs' own words are of the rest, web/locales/LANG/panels.ftl): each element of static/index.html
// with a `data-l10n-id` gets the message's attributes and, when the message has a text, that text, escaped,
// as the page writes them in another language (web/l10n/l10n.js, translatePage). An element whose
// message has a text holds text only; one that holds other elements (a region, a list of links) or
// none at all (an input) takes a message of attributes only, whose children stay as they are.
const enBundle = new FluentBundle('en', { useIsolating: false });
const enErrors = enBundle.addResource(new FluentResource(`${enPage}\n${enRest}`));
if (enErrors.length) throw new Error(`bundle: web/locales/en: ${enErrors.join('; ')}`);
const escapeHtml = (/** @type {string} */ text) =>
  text.replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c] ?? c);
let filled = 0;
html = html.replace(
  /<([a-z0-9]+)([^>]*?) data-l10n-id="([a-z0-9-]+)"([^>]*)>(?:([^<]*)<\/\1>)?/g,
  (whole, tag, before, id, after, content) => {
    const message = enBundle.getMessage(id);
    if (!message) throw new Error(`bundle: index.html names ${id}, which web/locales/en has not`);
    if (content !== undefined && content.trim() !== '')
      throw new Error(`bundle: index.html writes text in ${id}: it is the message's`);
    if (content === undefined && message.value !== null)
      throw new Error(`bundle: ${id} has a text, but its element in index.html holds other elements or none`);
    let attrs = `${before} data-l10n-id="${id}"${after}`;
    for (const [name, pattern] of Object.entries(message.attributes)) {
      if (new RegExp(` ${name}=`).test(attrs)) throw new Error(`bundle: index.html writes ${id}'s ${name}`);
      attrs += ` ${name}="${escapeHtml(enBundle.formatPattern(pattern))}"`;
    }
    filled++;
    if (content === undefined) return `<${tag}${attrs}>`;
    const text = message.value === null ? '' : escapeHtml(enBundle.formatPattern(message.value));
    return `<${tag}${attrs}>${text}</${tag}>`;
  },
);
if (filled !== html.split(' data-l10n-id=').length - 1)
  throw new Error('bundle: an element of index.html with a data-l10n-id was not filled');
writeFileSync(join(dist, 'index.html'), html);

// The service worker, with the list of files it fetches when it installs: every hashed file of
// this build, KaTeX's stylesheet and fonts, and the walkthrough's diagram.
const fonts = readdirSync(join(dist, 'vendor', 'katex', 'fonts')).map((f) => `vendor/katex/fonts/${f}`);
const precache = [
  ...readdirSync(out).map((f) => `web/${f}`),
  styleName,
  'vendor/katex/katex.min.css',
  ...fonts,
  'structure.svg',
];
const sw = once(
  readFileSync('static/sw.js', 'utf8'),
  'const PRECACHE = [];',
  `const PRECACHE = ${JSON.stringify(precache)};`,
);
writeFileSync(join(dist, 'sw.js'), sw);
