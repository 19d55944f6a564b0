// CPU time of whole processes, for the benches that compare two programs side by side.
import { spawnSync } from 'node:child_process';

/** CPU seconds (user + system) of `argv` run as a whole process, its output discarded. */
export function cpu(argv) {
  const quoted = argv.map((a) => `'${a.replaceAll("'", "'\\''")}'`).join(' ');
  const out = spawnSync('bash', ['-c', `${quoted} > /dev/null 2>&1; times`], { encoding: 'utf8' })
    .stdout.trim()
    .split('\n');
  // `times`: the shell's own line, then its children's: "0m1.234s 0m0.010s".
  return out[1]
    .split(' ')
    .map((t) => {
      const [, m, s] = /(\d+)m([\d.]+)s/.exec(t);
      return 60 * Number(m) + Number(s);
    })
    .reduce((a, b) => a + b, 0);
}
