// Compile a .ksy with the official Kaitai Struct compiler (npm kaitai-struct-compiler).
//
//   node tools/kaitai/compile.js LANGUAGE INPUT.ksy OUTDIR
//
// Writes every file the compiler returns into OUTDIR; any compiler error exits 1 with the
// compiler's message. No imports between .ksy files are needed, so no importer is given.
// A type whose `-ilahrs-not-for` key lists LANGUAGE is left out for it: the construct target, for
// one, has no stream position, which the `capture` type reads (E40).
"use strict";

const fs = require("fs");
const path = require("path");
const yaml = require("js-yaml");
const compiler = require("kaitai-struct-compiler");

async function main(argv) {
  if (argv.length !== 3) {
    throw new Error("usage: node compile.js LANGUAGE INPUT.ksy OUTDIR");
  }
  const [language, input, outdir] = argv;
  if (!compiler.languages.includes(language)) {
    throw new Error(`ksc ${compiler.version} has no target ${language}`);
  }
  const ksy = yaml.load(fs.readFileSync(input, "utf8"));
  for (const [name, type] of Object.entries(ksy.types || {})) {
    if ((type["-ilahrs-not-for"] || []).includes(language)) {
      delete ksy.types[name];
    }
  }
  const files = await compiler.compile(language, ksy, null, false);
  fs.mkdirSync(outdir, { recursive: true });
  for (const name of Object.keys(files).sort()) {
    fs.writeFileSync(path.join(outdir, name), files[name]);
    console.log(`ksc ${compiler.version} ${language}: ${path.join(outdir, name)}`);
  }
}

main(process.argv.slice(2)).catch((err) => {
  console.error(`ksc: ${String(err)}`);
  process.exit(1);
});
