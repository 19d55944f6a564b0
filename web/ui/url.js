// The address bar holds the current scenario in the core's compact codec (`?v=1&preset=...`).
// History entries carry {scenario, ran}: an edit replaces an entry that has not been run yet and
// pushes a new one after a run, so Back and Forward move between scenarios that were run.

/** The preset the page opens with when the address names no scenario. */
export const DEFAULT_PRESET = 'sine200';
export const DEFAULT_SCENARIO = `v=1&preset=${DEFAULT_PRESET}`;

/** The scenario text in the address bar, or the default when there is none. */
export function scenarioFromUrl() {
  const text = location.search.slice(1);
  return text === '' || challengeFromUrl() ? DEFAULT_SCENARIO : text;
}

/**
 * The challenge in the address bar, or null: `?c=1&…` is a challenge link and `?challenge=NAME` a
 * built-in, each with `&try.FIELD=…` a submission. Returns {challenge, submission}: the link the
 * core opens the challenge from (it reads no `try.` part) and the whole submission text, if any.
 */
export function challengeFromUrl() {
  const text = location.search.slice(1);
  const keys = [...new URLSearchParams(text).keys()];
  if (keys[0] === 'challenge') {
    const tries = keys.length > 1;
    return { challenge: text, submission: tries ? text : null };
  }
  // A stray character pasted before `c=` is the core's to name.
  if (!/^[^A-Za-z0-9&]*c=/.test(text)) return null;
  return { challenge: text, submission: text };
}

/**
 * While a challenge is open the address holds its link (then the student's submission link),
 * not the scenario: edits and runs leave it alone.
 * @type {string | null}
 */
let heldQuery = null;

/**
 * Holds `query` (a challenge or submission link) in the address bar, in place of the scenario.
 * @param {string} query
 */
export function holdAddress(query) {
  heldQuery = query;
  history.replaceState(history.state, '', `${location.pathname}?${query}${location.hash}`);
}

/**
 * The address of `scenario`: the fragment (#sweep=...) holds the analysis settings and stays
 * across scenario edits.
 * @param {string} scenario
 */
function urlFor(scenario) {
  return `${location.pathname}?${scenario}${location.hash}`;
}

function fragmentEntries() {
  return location.hash
    .slice(1)
    .split('&')
    .filter(Boolean)
    .map((p) => p.split('=', 2));
}

/**
 * The value of `key` in the URL fragment (`#key=value&...`), or null. Values are kept as written.
 * @param {string} key
 */
export function fragment(key) {
  return fragmentEntries().find(([k]) => k === key)?.[1] ?? null;
}

/**
 * The pinned scenarios of a `pins` fragment value (`a|b|...`, each URI-encoded), and the parts
 * that do not decode, which are left out.
 * @param {string} value
 */
export function decodePins(value) {
  const scenarios = [];
  const malformed = [];
  for (const part of value.split('|')) {
    try {
      scenarios.push(decodeURIComponent(part));
    } catch {
      malformed.push(part);
    }
  }
  return { scenarios, malformed };
}

/**
 * Sets (or, with null, removes) `key` in the URL fragment without a new history entry.
 * @param {string} key
 * @param {string | null} value
 */
export function setFragment(key, value) {
  const entries = fragmentEntries().filter(([k]) => k !== key);
  if (value !== null) entries.push([key, value]);
  history.replaceState(
    history.state,
    '',
    `${location.pathname}${location.search}#${entries.map((e) => e.join('=')).join('&')}`,
  );
}

/**
 * A history entry's state: the scenario in the address bar and whether it was run.
 * @typedef {{scenario: string, ran: boolean}} Entry
 */

/**
 * Puts `scenario` in the address bar as an edit of the current entry.
 * @param {string} scenario
 */
export function showScenario(scenario) {
  if (heldQuery !== null) return;
  /** @type {Entry | null} */
  const state = history.state;
  if (state && state.scenario === scenario) return;
  if (state && state.ran) history.pushState({ scenario, ran: false }, '', urlFor(scenario));
  else history.replaceState({ scenario, ran: false }, '', urlFor(scenario));
}

/**
 * Marks the current entry as run (pushing it first if the address bar holds another scenario).
 * @param {string} scenario
 */
export function markRun(scenario) {
  if (heldQuery !== null) return;
  /** @type {Entry | null} */
  const state = history.state;
  if (state && state.scenario !== scenario && state.ran) {
    history.pushState({ scenario, ran: true }, '', urlFor(scenario));
  } else {
    history.replaceState({ scenario, ran: true }, '', urlFor(scenario));
  }
}
