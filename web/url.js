// The address bar holds the current scenario in the core's compact codec (`?v=1&preset=...`).
// History entries carry {scenario, ran}: an edit replaces an entry that has not been run yet and
// pushes a new one after a run, so Back and Forward move between scenarios that were run.

export const DEFAULT_SCENARIO = 'v=1&preset=sine200';

/** The scenario text in the address bar, or the default when there is none. */
export function scenarioFromUrl() {
  const text = location.search.replace(/^\?/, '');
  return text === '' ? DEFAULT_SCENARIO : text;
}

/** The preset named in a (possibly invalid) scenario string, for falling back. */
export function presetNamed(text) {
  const match = /(?:^|&)preset=([A-Za-z0-9_-]+)/.exec(text);
  return match ? match[1] : null;
}

function urlFor(scenario) {
  return `${location.pathname}?${scenario}`;
}

/** Puts `scenario` in the address bar as an edit of the current entry. */
export function showScenario(scenario) {
  const state = history.state;
  if (state && state.scenario === scenario) return;
  if (state && state.ran) history.pushState({ scenario, ran: false }, '', urlFor(scenario));
  else history.replaceState({ scenario, ran: false }, '', urlFor(scenario));
}

/** Marks the current entry as run (pushing it first if the address bar holds another scenario). */
export function markRun(scenario) {
  const state = history.state;
  if (state && state.scenario !== scenario && state.ran) {
    history.pushState({ scenario, ran: true }, '', urlFor(scenario));
  } else {
    history.replaceState({ scenario, ran: true }, '', urlFor(scenario));
  }
}
