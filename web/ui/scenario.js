// Reading the core's description of a scenario (its `describe`): the page reads fields from it,
// never from the scenario's text.

/** The value the scenario holds for `key`, as the codec writes it, or null. */
export function fieldValue(info, key) {
  return info.fields.find((f) => f.key === key)?.value ?? null;
}
