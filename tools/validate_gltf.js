#!/usr/bin/env node
// Runs the Khronos glTF-Validator (npm package gltf-validator, installed into tools/node_modules
// by tools/setup-deps.sh) on .gltf/.glb files and prints one JSON line per file, in order:
//   {"file": ..., "errors": N, "warnings": N, "infos": N, "hints": N,
//    "error_codes": {"CODE": count, ...}, "warning_codes": {...}}
// Exit codes: 0 when the validator ran (whatever it found), 2 when a file cannot be read,
// 3 when the validator package is not installed (callers then skip, not fail). Several files
// in one run share the validator's start-up (about 0.3 s).
'use strict';

const fs = require('fs');
const path = require('path');

function fail(code, message) {
  process.stderr.write(`validate_gltf: ${message}\n`);
  process.exit(code);
}

if (process.argv.length < 3) fail(2, 'usage: node tools/validate_gltf.js FILE.gltf|FILE.glb...');
const files = process.argv.slice(2).map((f) => path.resolve(f));

let validator;
try {
  validator = require('gltf-validator');
} catch (e) {
  fail(3, 'the gltf-validator package is not installed (run: npm ci --prefix tools)');
}

// Severity numbers of the validator's report: 0 error, 1 warning, 2 info, 3 hint.
const kSeverityNames = ['errors', 'warnings', 'infos', 'hints'];

async function validate(file) {
  let bytes;
  try {
    bytes = fs.readFileSync(file);
  } catch (e) {
    fail(2, `cannot read ${file}: ${e.message}`);
  }
  // Side files (buffers, images) are read relative to the asset, as a glTF client would; a URI
  // the validator cannot load is reported by the validator itself (IO_ERROR), not here.
  const folder = path.dirname(file);
  const readSideFile = (uri) =>
    new Promise((resolve, reject) => {
      fs.readFile(path.resolve(folder, decodeURIComponent(uri)), (err, data) => {
        if (err) reject(err.toString());
        else resolve(new Uint8Array(data));
      });
    });
  const report = await validator.validateBytes(new Uint8Array(bytes), {
    uri: path.basename(file),
    maxIssues: 0,  // unlimited: the counts must be complete
    externalResourceFunction: readSideFile,
  });
  const summary = {file, errors: 0, warnings: 0, infos: 0, hints: 0, error_codes: {}, warning_codes: {}};
  for (const message of report.issues.messages) {
    const name = kSeverityNames[message.severity];
    if (name === undefined) continue;
    summary[name] += 1;
    const codes = message.severity === 0 ? summary.error_codes : message.severity === 1 ? summary.warning_codes : null;
    if (codes) codes[message.code] = (codes[message.code] || 0) + 1;
  }
  return summary;
}

(async () => {
  for (const file of files) {
    let summary;
    try {
      summary = await validate(file);
    } catch (error) {
      fail(2, `validator failed on ${file}: ${error}`);
    }
    process.stdout.write(JSON.stringify(summary) + '\n');
  }
})();
