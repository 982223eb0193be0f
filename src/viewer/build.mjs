// Bundles the viewer (src/main.js + three.js) into one minified IIFE script.
// usage: node build.mjs OUTFILE   (run by CMake at build time; `npm run build` -> dist/viewer.js)
import { build } from 'esbuild';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const outfile = process.argv[2] ?? join(here, 'dist', 'viewer.js');
await build({
  entryPoints: [join(here, 'src', 'main.js')],
  bundle: true,
  minify: true,
  format: 'iife',
  target: 'es2020',
  charset: 'ascii',
  legalComments: 'eof', // keeps three.js's MIT notice in the bundle
  logLevel: 'warning',
  outfile,
});
