#!/usr/bin/env node
// Writes scenes/cornell_bunny.dae: the Stanford bunny (npm package `bunny`, public domain) standing
// on the floor of scenes/cornell_empty.dae. The box is read from that file, so the two never drift.
//
// Re-run (the .dae is committed; run this only to regenerate it):
//   cd /tmp && npm install bunny
//   NODE_PATH=/tmp/node_modules node course/bunny_to_dae.mjs            # from the repository root
// Options: --out FILE (default scenes/cornell_bunny.dae), --subdivide N (split every triangle into
// 4, N times: the same shape with 4^N times the triangles, for loader and BVH benchmarks).
//
// The mesh keeps the package's own coordinates (Y up); the node's <matrix> scales it to 0.9 m tall,
// stands it on the floor and turns it into the file's Z-up axes, as a Blender export would.
// Smooth vertex normals (angle-weighted) go into <vertices>, so <p> needs one index per corner.
import { readFileSync, writeFileSync, renameSync } from 'node:fs';
import { createRequire } from 'node:module';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(name);
  return i >= 0 && i + 1 < args.length ? args[i + 1] : fallback;
};
const out = option('--out', 'scenes/cornell_bunny.dae');
const subdivisions = Number(option('--subdivide', '0'));
if (!Number.isInteger(subdivisions) || subdivisions < 0 || subdivisions > 5) {
  console.error('--subdivide: expected an integer in 0..5');
  process.exit(2);
}

const require = createRequire(import.meta.url);
let bunny;
try {
  bunny = require('bunny');
} catch {
  console.error('cannot find the npm package "bunny": run `cd /tmp && npm install bunny` and set NODE_PATH=/tmp/node_modules');
  process.exit(1);
}

let positions = bunny.positions.map((p) => p.slice());
let cells = bunny.cells.map((c) => c.slice());

// 1 -> 4 midpoint subdivision; shared edges get one midpoint so the mesh stays closed.
for (let s = 0; s < subdivisions; s++) {
  const mid = new Map();
  const midpoint = (a, b) => {
    const key = a < b ? `${a},${b}` : `${b},${a}`;
    if (!mid.has(key)) {
      mid.set(key, positions.length);
      positions.push([0, 1, 2].map((k) => (positions[a][k] + positions[b][k]) / 2));
    }
    return mid.get(key);
  };
  const next = [];
  for (const [a, b, c] of cells) {
    const ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
    next.push([a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]);
  }
  cells = next;
}

// Smooth normals: each face adds its unit normal weighted by its corner angle.
const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const unit = (a) => { const l = Math.hypot(...a); return l > 0 ? a.map((x) => x / l) : a; };
const normals = positions.map(() => [0, 0, 0]);
for (const cell of cells) {
  const n = unit(cross(sub(positions[cell[1]], positions[cell[0]]), sub(positions[cell[2]], positions[cell[0]])));
  for (let k = 0; k < 3; k++) {
    const p = positions[cell[k]];
    const e1 = unit(sub(positions[cell[(k + 1) % 3]], p)), e2 = unit(sub(positions[cell[(k + 2) % 3]], p));
    const angle = Math.acos(Math.max(-1, Math.min(1, dot(e1, e2))));
    for (let j = 0; j < 3; j++) normals[cell[k]][j] += angle * n[j];
  }
}

// Placement in the world (Y up): 0.9 m tall, centred in x, feet on the floor, a little back.
const lo = [0, 1, 2].map((k) => Math.min(...positions.map((p) => p[k])));
const hi = [0, 1, 2].map((k) => Math.max(...positions.map((p) => p[k])));
const s = 0.9 / (hi[1] - lo[1]);
const t = [-s * (lo[0] + hi[0]) / 2, -s * lo[1], -0.1 - s * (lo[2] + hi[2]) / 2];
// World (X, Y, Z) = s p + t; the file's Z-up axes are (x, y, z) = (-X, Z, Y).
const r = (x) => Number(x.toFixed(6));
const matrix = [
  [-s, 0, 0, -t[0]],
  [0, 0, s, t[2]],
  [0, s, 0, t[1]],
  [0, 0, 0, 1],
].map((row) => row.map(r).join(' ')).join('  ');

const fmt = (x, digits) => { const v = Number(x.toFixed(digits)); return Object.is(v, -0) ? '0' : String(v); };
const lines = (rows, per) => {
  const outLines = [];
  for (let i = 0; i < rows.length; i += per) outLines.push(rows.slice(i, i + per).join('  '));
  return outLines.join('\n');
};
const posText = lines(positions.map((p) => p.map((x) => fmt(x, 6)).join(' ')), 8);
const nrmText = lines(normals.map((n) => unit(n).map((x) => fmt(x, 5)).join(' ')), 8);
const idxText = lines(cells.map((c) => c.join(' ')), 16);

// One <source> of xyz triples, as Blender writes them.
const source = (name, text, count) => `        <source id="Bunny-mesh-${name}">
          <float_array id="Bunny-mesh-${name}-array" count="${count * 3}">
${text}
          </float_array>
          <technique_common>
            <accessor source="#Bunny-mesh-${name}-array" count="${count}" stride="3">
              <param name="X" type="float"/>
              <param name="Y" type="float"/>
              <param name="Z" type="float"/>
            </accessor>
          </technique_common>
        </source>
`;

const geometry = `    <geometry id="Bunny-mesh" name="Bunny">
      <mesh>
${source('positions', posText, positions.length)}${source('normals', nrmText, normals.length)}        <vertices id="Bunny-mesh-vertices">
          <input semantic="POSITION" source="#Bunny-mesh-positions"/>
          <input semantic="NORMAL" source="#Bunny-mesh-normals"/>
        </vertices>
        <triangles material="bunny-material" count="${cells.length}">
          <input semantic="VERTEX" source="#Bunny-mesh-vertices" offset="0"/>
          <p>
${idxText}
          </p>
        </triangles>
      </mesh>
    </geometry>
`;
const node = `      <node id="Bunny" name="Bunny" type="NODE">
        <matrix sid="transform">${matrix}</matrix>
        <instance_geometry url="#Bunny-mesh" name="Bunny">
          <bind_material>
            <technique_common>
              <instance_material symbol="bunny-material" target="#white-material"/>
            </technique_common>
          </bind_material>
        </instance_geometry>
      </node>
`;

// Splice into the empty box: geometry before </library_geometries>, node before </visual_scene>.
let box = readFileSync(new URL('../scenes/cornell_empty.dae', import.meta.url), 'utf8');
const splice = (text, marker, insert) => {
  const at = text.indexOf(marker);
  if (at < 0) throw new Error(`cornell_empty.dae has no ${marker}`);
  return text.slice(0, at) + insert + text.slice(at);
};
box = box.replace(/<!-- pathlab: an empty Cornell box,/, '<!-- pathlab: the Stanford bunny (npm package `bunny`, public domain; written by the course's converter) in a Cornell box,');
box = splice(box, '  </library_geometries>', geometry);
box = splice(box, '    </visual_scene>', node);
const tmp = `${out}.tmp`;
writeFileSync(tmp, box);
renameSync(tmp, out);
console.log(`wrote ${out}: ${cells.length} triangles, ${positions.length} vertices`);
