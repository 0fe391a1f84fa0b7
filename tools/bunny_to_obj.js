// Writes the `bunny` npm package's mesh as OBJ on standard output.
// Usage: node tools/bunny_to_obj.js path/to/bunny/index.js > bunny.obj
'use strict';
const path = require('path');
const { positions, cells } = require(path.resolve(process.argv[2]));
const lines = ['# The Stanford bunny, from the npm package bunny 1.0.1'];
for (const [x, y, z] of positions) lines.push(`v ${x} ${y} ${z}`);
// The package's cells count from 0; OBJ counts from 1.
for (const cell of cells) lines.push('f ' + cell.map((i) => i + 1).join(' '));
process.stdout.write(lines.join('\n') + '\n');
