// Loads one of the web demo's two builds (scripts/build_web.sh): the WebGPU one where
// the browser gives a WebGPU adapter, else the WebGL2 one. `?build=webgl2` or `?build=webgpu` forces one (tests, bug reports).
const asked = new URLSearchParams(location.search).get('build');
const adapter = asked ? null : await navigator.gpu?.requestAdapter().catch(() => null);
const build = asked === 'webgpu' || asked === 'webgl2' ? asked : adapter ? 'webgpu' : 'webgl2';
// The browser test reads which build runs, and the app's controls through the bindings.
window.linkageLabBuild = build;
const bindings = await import(`./${build}/linkage-lab.js`);
window.wasmBindings = bindings;
await bindings.default();
