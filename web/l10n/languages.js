// The languages the page speaks, each by its code and its own name.
export const LANGUAGES = /** @type {const} */ ([
  ['en', 'English'],
  ['de', 'Deutsch'],
  ['es', 'Español'],
  ['fr', 'Français'],
  ['zh-CN', '简体中文'],
  ['ja', '日本語'],
]);
