#!/usr/bin/env node
// A second external engine, written from docs/external-engines.md alone ("Matching mysim's
// integrators to the last bit"), in JavaScript for Node.js with no packages:
//
//     node jsim.mjs MODEL_JSON OUT_DIR
//
// It follows the model's integrator (euler, symplectic-euler, verlet, trapezoidal, rk4, dopri5,
// xpbd) and writes times.npy and trajectory.npy. tests/protocol_rules_test.cpp holds it to mysim:
// if the page leaves out a rule, the two part by more than round-off and the test says where.
import fs from 'node:fs';
import path from 'node:path';

const [modelPath, outDir] = process.argv.slice(2);
if (!modelPath || !outDir) {
  console.error('usage: jsim.mjs MODEL_JSON OUT_DIR');
  process.exit(2);
}
const model = JSON.parse(fs.readFileSync(modelPath, 'utf8'));
const P = model.particles;
const n = P.count;
const mass = P.mass;
const pinned = P.pinned;
const S = model.springs;
const springCount = S.count;
const damped = S.damping.some((c) => c !== 0);
const gravity = model.gravity;
const drag = model.drag;
const pins = model.pin_motion;
const colliders = model.colliders;
const settings = model.integrator;

// ---- npy ----------------------------------------------------------------------------------
function readNpy(file) {
  const bytes = fs.readFileSync(file);
  const major = bytes[6];
  const headerLength = major === 1 ? bytes.readUInt16LE(8) : bytes.readUInt32LE(8);
  const start = major === 1 ? 10 + headerLength : 12 + headerLength;
  const header = bytes.subarray(major === 1 ? 10 : 12, start).toString('latin1');
  if (!header.includes("'<f8'")) throw new Error(`${file}: expected float64`);
  const shape = header.match(/\(([^)]*)\)/)[1].split(',').filter((s) => s.trim()).map(Number);
  const copy = new Uint8Array(bytes.subarray(start));  // aligned
  return { shape, data: new Float64Array(copy.buffer, 0, copy.byteLength / 8) };
}

function writeNpy(file, shape, values) {
  let header = `{'descr': '<f8', 'fortran_order': False, 'shape': (${shape.join(', ')}${
    shape.length === 1 ? ',' : ''}), }`;
  while ((10 + header.length + 1) % 64 !== 0) header += ' ';
  header += '\n';
  const head = Buffer.alloc(10);
  head.write('\x93NUMPY', 0, 'latin1');
  head[6] = 1;
  head[7] = 0;
  head.writeUInt16LE(header.length, 8);
  const body = Buffer.from(new Float64Array(values).buffer);
  fs.writeFileSync(file, Buffer.concat([head, Buffer.from(header, 'latin1'), body]));
}

// ---- forces -------------------------------------------------------------------------------
let windTable = null;
if (model.wind) windTable = readNpy(path.join(path.dirname(modelPath), model.wind.force_table));

// Each particle's springs in spring index order, with the other end.
const incident = Array.from({ length: n }, () => []);
for (let s = 0; s < springCount; ++s) {
  incident[S.i[s]].push([s, S.j[s]]);
  incident[S.j[s]].push([s, S.i[s]]);
}
const sigma = new Float64Array(springCount);
const w = 2 * Math.PI * (pins ? pins.frequency : 0);
const pinOffset = (t) => pins.amplitude * Math.sin(w * t);
const pinVelocity = (t) => (pins ? pins.amplitude * w * Math.cos(w * t) : 0);
const pinAcceleration = (t) => (pins ? -pins.amplitude * w * w * Math.sin(w * t) : 0);

function acceleration(t, x, v, a) {
  for (let s = 0; s < springCount; ++s) {
    const i = 3 * S.i[s], j = 3 * S.j[s];
    const dx = x[j] - x[i], dy = x[j + 1] - x[i + 1], dz = x[j + 2] - x[i + 2];
    const invL = 1 / Math.sqrt(dx * dx + dy * dy + dz * dz);
    let value = S.stiffness[s] * (1 - S.rest_length[s] * invL);
    if (damped) {
      const dw = dx * (v[j] - v[i]) + dy * (v[j + 1] - v[i + 1]) + dz * (v[j + 2] - v[i + 2]);
      value += S.damping[s] * dw * invL * invL;
    }
    sigma[s] = value;
  }
  const window = windTable ? Math.floor(t / model.wind.gust_period) : 0;
  for (let p = 0; p < n; ++p) {
    if (pinned[p]) {
      const A = pinAcceleration(t);
      for (let c = 0; c < 3; ++c) a[3 * p + c] = pins ? A * pins.axis[c] : 0;
      continue;
    }
    const f = [0, 0, 0];
    for (let c = 0; c < 3; ++c) f[c] = mass[p] * gravity[c] - drag * v[3 * p + c];
    if (windTable) {
      const W = windTable.data[window * n + p];
      for (let c = 0; c < 3; ++c) f[c] += W * model.wind.direction[c];
    }
    for (const [s, q] of incident[p]) {
      for (let c = 0; c < 3; ++c) f[c] += sigma[s] * (x[3 * q + c] - x[3 * p + c]);
    }
    const inverse = 1 / mass[p];
    for (let c = 0; c < 3; ++c) a[3 * p + c] = f[c] * inverse;
  }
}

// F(t, y) with y = [x (3N), v (3N)].
function derivative(t, y, out) {
  const x = y.subarray(0, 3 * n), v = y.subarray(3 * n);
  acceleration(t, x, v, out.subarray(3 * n));
  for (let p = 0; p < n; ++p) {
    for (let c = 0; c < 3; ++c) {
      out[3 * p + c] = pinned[p] ? (pins ? pinVelocity(t) * pins.axis[c] : 0) : v[3 * p + c];
    }
  }
}

// ---- contacts -----------------------------------------------------------------------------
const norm = (u) => Math.sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
const sub = (u, v) => [u[0] - v[0], u[1] - v[1], u[2] - v[2]];

function signedDistance(k, P) {
  if (k.type === 'sphere') return norm(sub(P, k.center)) - k.radius;
  if (k.type === 'plane') {
    const d = sub(P, k.point);
    return k.normal[0] * d[0] + k.normal[1] * d[1] + k.normal[2] * d[2];
  }
  const q = [0, 1, 2].map((c) => Math.abs(P[c] - k.center[c]) - k.half_extents[c]);
  return norm(q.map((e) => Math.max(e, 0))) + Math.min(Math.max(...q), 0);
}

// The surface point and normal of a contact, or null.
function contact(k, index, x) {
  const e = k.margin;
  if (k.type === 'sphere') {
    const d = sub(x, k.center);
    const r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    const R = k.radius + e;
    if (r2 >= R * R) return null;
    const r = Math.sqrt(r2);
    const nrm = r > 0 ? d.map((c) => c / r) : [0, 1, 0];
    return [nrm.map((c, i) => k.center[i] + R * c), nrm];
  }
  if (k.type === 'plane') {
    const d = signedDistance(k, x);
    if (d >= e) return null;
    return [x.map((c, i) => c + (e - d) * k.normal[i]), k.normal];
  }
  const H = k.half_extents, C = k.center;
  const u = sub(x, C);
  const q = [0, 1, 2].map((c) => Math.abs(u[c]) - H[c]);
  if (Math.max(...q) > 0) {
    const B = [0, 1, 2].map((c) => C[c] + Math.min(Math.max(u[c], -H[c]), H[c]));
    const out = sub(x, B);
    const D = norm(out);
    if (D >= e) return null;
    const nrm = out.map((c) => c / D);
    return [B.map((c, i) => c + e * nrm[i]), nrm];
  }
  const exits = [];
  for (let axis = 0; axis < 3; ++axis) {
    const near = u[axis] < 0 ? -1 : 1;
    for (const side of [near, -near]) {
      const Pt = x.slice();
      Pt[axis] = C[axis] + side * (H[axis] + e);
      const nrm = [0, 0, 0];
      nrm[axis] = side;
      exits.push({ depth: H[axis] - side * u[axis], P: Pt, n: nrm });
    }
  }
  exits.sort((a, b) => a.depth - b.depth);  // Array.prototype.sort is stable
  const free = exits.find((ex) => colliders.every((o, j) => j === index || signedDistance(o, ex.P) >= 0));
  const chosen = free || exits[0];
  return [chosen.P, chosen.n];
}

// ---- after every step ---------------------------------------------------------------------
const start = Float64Array.from(P.position.flat());
function afterStep(t, y) {
  const x = y.subarray(0, 3 * n), v = y.subarray(3 * n);
  for (let p = 0; p < n; ++p) {
    if (!pinned[p]) continue;
    for (let c = 0; c < 3; ++c) {
      x[3 * p + c] = start[3 * p + c] + (pins ? pinOffset(t) * pins.axis[c] : 0);
      v[3 * p + c] = pins ? pinVelocity(t) * pins.axis[c] : 0;
    }
  }
  for (let p = 0; p < n; ++p) {
    if (pinned[p]) continue;
    colliders.forEach((k, index) => {
      const hit = contact(k, index, Array.from(x.subarray(3 * p, 3 * p + 3)));
      if (!hit) return;
      const [Pt, nrm] = hit;
      for (let c = 0; c < 3; ++c) x[3 * p + c] = Pt[c];
      const vn = v[3 * p] * nrm[0] + v[3 * p + 1] * nrm[1] + v[3 * p + 2] * nrm[2];
      if (vn < 0) for (let c = 0; c < 3; ++c) v[3 * p + c] -= vn * nrm[c];
    });
  }
}

// ---- the integrators ----------------------------------------------------------------------
const N6 = 6 * n;
const y = new Float64Array(N6);
y.set(P.position.flat(), 0);
y.set(P.velocity.flat(), 3 * n);
const scratch = () => new Float64Array(N6);
const k1 = scratch(), k2 = scratch(), k3 = scratch(), k4 = scratch(), trial = scratch();
let evaluations = 0;

function explicitStep(name, t, h) {
  const x = y.subarray(0, 3 * n), v = y.subarray(3 * n);
  if (name === 'euler') {
    derivative(t, y, k1);
    for (let i = 0; i < N6; ++i) y[i] += h * k1[i];
    evaluations += 1;
  } else if (name === 'symplectic-euler') {
    const a = k1.subarray(0, 3 * n);
    acceleration(t, x, v, a);
    for (let i = 0; i < 3 * n; ++i) v[i] += h * a[i];
    for (let i = 0; i < 3 * n; ++i) x[i] += h * v[i];
    evaluations += 1;
  } else if (name === 'verlet') {
    const a = k1.subarray(0, 3 * n), vp = k2.subarray(0, 3 * n);
    acceleration(t, x, v, a);
    for (let i = 0; i < 3 * n; ++i) v[i] += (h / 2) * a[i];
    for (let i = 0; i < 3 * n; ++i) x[i] += h * v[i];
    for (let i = 0; i < 3 * n; ++i) vp[i] = v[i] + (h / 2) * a[i];
    acceleration(t + h, x, vp, a);
    for (let i = 0; i < 3 * n; ++i) v[i] += (h / 2) * a[i];
    evaluations += 2;
  } else if (name === 'trapezoidal') {
    derivative(t, y, k1);
    for (let i = 0; i < N6; ++i) trial[i] = y[i] + h * k1[i];
    derivative(t + h, trial, k2);
    for (let i = 0; i < N6; ++i) y[i] += (h / 2) * (k1[i] + k2[i]);
    evaluations += 2;
  } else if (name === 'rk4') {
    derivative(t, y, k1);
    for (let i = 0; i < N6; ++i) trial[i] = y[i] + (h / 2) * k1[i];
    derivative(t + h / 2, trial, k2);
    for (let i = 0; i < N6; ++i) trial[i] = y[i] + (h / 2) * k2[i];
    derivative(t + h / 2, trial, k3);
    for (let i = 0; i < N6; ++i) trial[i] = y[i] + h * k3[i];
    derivative(t + h, trial, k4);
    for (let i = 0; i < N6; ++i) y[i] += (h / 6) * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    evaluations += 4;
  } else {
    throw new Error(`jsim: integrator ${name} not implemented`);
  }
  afterStep(t + h, y);
}

// Dormand-Prince 5(4), the standard tableau.
const DC = [0, 1 / 5, 3 / 10, 4 / 5, 8 / 9, 1, 1];
const DA = [[], [1 / 5], [3 / 40, 9 / 40], [44 / 45, -56 / 15, 32 / 9],
  [19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729],
  [9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656],
  [35 / 384, 0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84]];
const DE = [71 / 57600, 0, -71 / 16695, 71 / 1920, -17253 / 339200, 22 / 525, -1 / 40];
const stages = Array.from({ length: 7 }, scratch);
let proposed = 0;
function dopri5Step(t0, H) {
  const atol = settings.abs_tolerance, rtol = settings.rel_tolerance;
  const tEnd = t0 + H;
  let t = t0;
  if (proposed <= 0) proposed = H;
  while (tEnd - t > 1e-12 * H) {
    const last = proposed >= tEnd - t;
    const h = last ? tEnd - t : proposed;
    for (let s = 0; s < 7; ++s) {
      for (let i = 0; i < N6; ++i) {
        let value = y[i];
        for (let j = 0; j < s; ++j) if (DA[s][j] !== 0) value += h * DA[s][j] * stages[j][i];
        trial[i] = value;
      }
      derivative(t + DC[s] * h, trial, stages[s]);
    }
    evaluations += 7;
    let sum = 0;
    for (let i = 0; i < N6; ++i) {
      let e = 0;
      for (let s = 0; s < 7; ++s) if (DE[s] !== 0) e += h * DE[s] * stages[s][i];
      const scale = atol + rtol * Math.max(Math.abs(y[i]), Math.abs(trial[i]));
      sum += (e / scale) ** 2;
    }
    const err = Math.sqrt(sum / N6);
    const factor = Number.isFinite(err)
      ? Math.min(5, Math.max(0.2, 0.9 * Math.max(err, 1e-10) ** -0.2)) : 0.2;
    if (err <= 1) {
      y.set(trial);
      t = last ? tEnd : t + h;
      afterStep(t, y);
      if (!last || factor < 1) proposed = h * factor;
    } else {
      proposed = h * factor;
    }
  }
}

// XPBD: springs coloured greedily in index order, Gauss-Seidel colour by colour.
let colours = null;
function colourSprings() {
  const used = Array.from({ length: n }, () => new Set());
  const result = [];
  for (let s = 0; s < springCount; ++s) {
    let c = 0;
    while (used[S.i[s]].has(c) || used[S.j[s]].has(c)) ++c;
    if (c === result.length) result.push([]);
    result[c].push(s);
    used[S.i[s]].add(c);
    used[S.j[s]].add(c);
  }
  return result;
}
function xpbdStep(t0, h) {
  colours ??= colourSprings();
  const substeps = settings.substeps, iterations = settings.iterations;
  const hs = h / substeps;
  const x = y.subarray(0, 3 * n), v = y.subarray(3 * n);
  const xPrev = new Float64Array(3 * n), lambda = new Float64Array(springCount);
  const wInv = mass.map((m, p) => (pinned[p] ? 0 : 1 / m));
  let t = t0;
  for (let sub = 0; sub < substeps; ++sub) {
    const window = windTable ? Math.floor(t / model.wind.gust_period) : 0;
    for (let p = 0; p < n; ++p) {
      if (pinned[p]) continue;
      for (let c = 0; c < 3; ++c) {
        let f = mass[p] * gravity[c] - drag * v[3 * p + c];
        if (windTable) f += windTable.data[window * n + p] * model.wind.direction[c];
        v[3 * p + c] += hs * wInv[p] * f;
      }
    }
    xPrev.set(x);
    t += hs;
    for (let p = 0; p < n; ++p) {
      for (let c = 0; c < 3; ++c) {
        x[3 * p + c] = pinned[p]
          ? start[3 * p + c] + (pins ? pinOffset(t) * pins.axis[c] : 0)
          : x[3 * p + c] + hs * v[3 * p + c];
      }
    }
    lambda.fill(0);
    for (let it = 0; it < iterations; ++it) {
      for (const colour of colours) {
        for (const s of colour) {
          const i = S.i[s], j = S.j[s];
          const wi = wInv[i], wj = wInv[j];
          if (wi + wj === 0) continue;
          const d = [0, 1, 2].map((c) => x[3 * i + c] - x[3 * j + c]);
          const length = norm(d);
          if (length === 0) continue;
          const u = d.map((c) => c / length);
          const alpha = 1 / (S.stiffness[s] * hs * hs);
          const gamma = S.damping[s] / (S.stiffness[s] * hs);
          let moved = 0;
          for (let c = 0; c < 3; ++c) {
            moved += u[c] * ((x[3 * i + c] - xPrev[3 * i + c]) - (x[3 * j + c] - xPrev[3 * j + c]));
          }
          const dl = (-(length - S.rest_length[s]) - alpha * lambda[s] - gamma * moved) /
                     ((1 + gamma) * (wi + wj) + alpha);
          for (let c = 0; c < 3; ++c) {
            x[3 * i + c] += wi * dl * u[c];
            x[3 * j + c] -= wj * dl * u[c];
          }
          lambda[s] += dl;
        }
      }
    }
    for (let i = 0; i < 3 * n; ++i) v[i] = (x[i] - xPrev[i]) / hs;
    afterStep(t, y);
  }
  evaluations += substeps;
  return t;
}

// ---- the run ------------------------------------------------------------------------------
const name = settings.name;
const times = [0];
const frames = [Array.from(y)];
let wanted = 1;
let t = 0;
const began = process.hrtime.bigint();
for (let step = 1; step <= model.steps; ++step) {
  if (name === 'dopri5') {
    dopri5Step(t, model.dt);
    t += model.dt;
  } else if (name === 'xpbd') {
    t = xpbdStep(t, model.dt);
  } else {
    explicitStep(name, t, model.dt);
    t += model.dt;
  }
  if (wanted < model.frame_steps.length && model.frame_steps[wanted] === step) {
    times.push(model.frame_times[wanted]);
    frames.push(Array.from(y));
    ++wanted;
  }
}
const seconds = Number(process.hrtime.bigint() - began) * 1e-9;

// Frames as (F, N, 6): x y z vx vy vz per particle.
const rows = [];
for (const f of frames) {
  for (let p = 0; p < n; ++p) {
    rows.push(f[3 * p], f[3 * p + 1], f[3 * p + 2], f[3 * n + 3 * p], f[3 * n + 3 * p + 1],
              f[3 * n + 3 * p + 2]);
  }
}
writeNpy(path.join(outDir, 'times.npy'), [times.length], times);
writeNpy(path.join(outDir, 'trajectory.npy'), [frames.length, n, 6], rows);
fs.writeFileSync(path.join(outDir, 'summary.json'), JSON.stringify(
  { wall_seconds: seconds, derivative_evaluations: evaluations, blowup: null }));
