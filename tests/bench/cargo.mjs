// Bench executables built by cargo, for the benches that run them as whole processes.
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';

/** Path of the executable of crate/benches/`name`.rs, built by cargo in the bench profile. */
export function benchExecutable(name) {
  const root = fileURLToPath(new URL('../../', import.meta.url));
  const p = spawnSync('cargo', ['bench', '--bench', name, '--no-run', '--message-format=json-render-diagnostics'], {
    cwd: root,
    encoding: 'utf8',
    stdio: ['ignore', 'pipe', 'pipe'],
    maxBuffer: 1 << 26,
  });
  if (p.status !== 0) throw new Error(`building crate/benches/${name}.rs failed\n${p.stderr}`);
  return p.stdout
    .split('\n')
    .filter((line) => line.startsWith('{'))
    .map((line) => JSON.parse(line))
    .find((m) => m.reason === 'compiler-artifact' && m.target.name === name && m.executable).executable;
}
