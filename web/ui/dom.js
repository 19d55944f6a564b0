// The page's one DOM helper.

/** A new `tag` element with `props` assigned and `children` appended. */
export function el(tag, props = {}, children = []) {
  const e = Object.assign(document.createElement(tag), props);
  e.append(...children);
  return e;
}
