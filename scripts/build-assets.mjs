// Copies the front-end files the service serves from node_modules (installed by `npm ci` from the
// pinned package-lock.json) into app/static/vendor/: three.js for the explorer, keeping three's
// own layout so that the page's import map ("three", "three/addons/") resolves; KaTeX (its
// minified script, stylesheet and WOFF2 fonts) for the explorer's mathematics; axe-core, which only the
// browser tests load (an accessibility audit of the explorer); Swagger UI for /docs and ReDoc
// for /redoc, so that the documentation pages work without any CDN.
// Run by `make assets` and the Dockerfile.
import { cpSync, mkdirSync, readdirSync, rmSync, writeFileSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const source = join(root, 'node_modules', 'three');
const target = join(root, 'app', 'static', 'vendor', 'three');
const files = [
  'LICENSE',
  'package.json',
  'build/three.module.js',
  'build/three.core.js',
  'examples/jsm/controls/OrbitControls.js',
  'examples/jsm/loaders/GLTFLoader.js',
  'examples/jsm/utils/BufferGeometryUtils.js',
  'examples/jsm/utils/SkeletonUtils.js',
];

rmSync(target, { recursive: true, force: true });
for (const file of files) {
  mkdirSync(dirname(join(target, file)), { recursive: true });
  cpSync(join(source, file), join(target, file));
}
const version = JSON.parse(readFileSync(join(source, 'package.json'), 'utf8')).version;
writeFileSync(join(target, 'VERSION'), `${version}\n`);
console.log(`three ${version}: ${files.length} files copied to app/static/vendor/three`);

// the browsers the page supports read WOFF2, the first format katex.css offers: the others stay
const katexFonts = readdirSync(join(root, 'node_modules', 'katex', 'dist', 'fonts'))
  .filter((name) => name.endsWith('.woff2'))
  .map((name) => `dist/fonts/${name}`);
const docs = {
  'swagger-ui': ['swagger-ui-dist', ['LICENSE', 'swagger-ui-bundle.js', 'swagger-ui.css', 'favicon-32x32.png']],
  redoc: ['redoc', ['LICENSE', 'bundles/redoc.standalone.js']],
  katex: ['katex', ['LICENSE', 'dist/katex.min.js', 'dist/katex.min.css', ...katexFonts]],
  'axe-core': ['axe-core', ['LICENSE', 'axe.min.js']],
};
for (const [name, [pkg, wanted]] of Object.entries(docs)) {
  const from = join(root, 'node_modules', pkg);
  const to = join(root, 'app', 'static', 'vendor', name);
  rmSync(to, { recursive: true, force: true });
  for (const file of wanted) {
    mkdirSync(dirname(join(to, file)), { recursive: true });
    cpSync(join(from, file), join(to, file));
  }
  const v = JSON.parse(readFileSync(join(from, 'package.json'), 'utf8')).version;
  writeFileSync(join(to, 'VERSION'), `${v}\n`);
  console.log(`${pkg} ${v}: ${wanted.length} files copied to app/static/vendor/${name}`);
}
