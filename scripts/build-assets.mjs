// Copies the three.js files the explorer loads from node_modules (installed by `npm ci` from the
// pinned package-lock.json) into app/static/vendor/three/, keeping three's own layout so that the
// page's import map ("three", "three/addons/") resolves. Run by `make assets` and the Dockerfile.
import { cpSync, mkdirSync, rmSync, writeFileSync, readFileSync } from 'node:fs';
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
