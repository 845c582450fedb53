// Runs the Khronos glTF validator on files Glint wrote.
// Usage: node validate_gltf.js NODE_MODULES_DIR FILE...
// Exit 0: no errors in any file; 1: errors (printed); 2: the validator is not installed.
'use strict';
const fs = require('fs');
const path = require('path');

const [modulesDir, ...files] = process.argv.slice(2);
let validator;
try {
    validator = require(path.join(modulesDir, 'gltf-validator'));
} catch (e) {
    console.error(`gltf-validator not found in ${modulesDir}: install it with ` +
                  `"npm install --prefix ${path.dirname(modulesDir)} gltf-validator"`);
    process.exit(2);
}

// External buffers and images, relative to the glTF's folder.
function resourceLoader(folder) {
    return (uri) => new Promise((resolve, reject) => {
        fs.readFile(path.join(folder, decodeURIComponent(uri)), (err, data) => {
            if (err) reject(err.toString()); else resolve(new Uint8Array(data));
        });
    });
}

async function validate(file) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
        uri: path.basename(file),
        externalResourceFunction: resourceLoader(path.dirname(file)),
        maxIssues: 100,
    });
    const issues = report.issues;
    console.log(`${path.basename(file)}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
                `${issues.numInfos} infos, ${issues.numHints} hints`);
    for (const m of issues.messages.filter((m) => m.severity <= 1))
        console.log(`  ${m.severity === 0 ? 'error' : 'warning'} ${m.code} at ${m.pointer}: ${m.message}`);
    return issues.numErrors;
}

(async () => {
    let errors = 0;
    for (const file of files) errors += await validate(file);
    process.exit(errors === 0 ? 0 : 1);
})().catch((e) => {
    console.error(e.toString());
    process.exit(1);
});
