// validate.js: runs the Khronos glTF-Validator over .glb files; prints each
// error and warning as "FILE: CODE at POINTER: message" and exits 1 when a
// file has any (infos and hints are printed with --verbose only).
'use strict';
const fs = require('fs');
const validator = require('gltf-validator');

async function main() {
    const args = process.argv.slice(2);
    const verbose = args[0] === '--verbose';
    const files = verbose ? args.slice(1) : args;
    if (files.length === 0) {
        console.error('usage: node validate.js [--verbose] FILE.glb...');
        process.exit(2);
    }
    let bad = 0;
    for (const f of files) {
        let bytes;
        try {
            bytes = new Uint8Array(fs.readFileSync(f));
        } catch (e) {
            console.error(`${f}: cannot read: ${e.message}`);
            bad++;
            continue;
        }
        const report = await validator.validateBytes(bytes, {maxIssues: 0});
        const n = report.issues;
        for (const m of n.messages) {
            if (m.severity <= 1 || verbose)
                console.log(`${f}: ${['error', 'warning', 'info', 'hint'][m.severity]} ` +
                            `${m.code} at ${m.pointer || m.offset || '-'}: ${m.message}`);
        }
        if (n.numErrors || n.numWarnings)
            bad++;
    }
    process.exit(bad ? 1 : 0);
}
main().catch((e) => { console.error(`validate.js: ${e.message || e}`); process.exit(1); });
