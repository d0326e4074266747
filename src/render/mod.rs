//! The mechanism view's GPU renderer: one instanced draw of signed-distance shapes
//! (`shaders/linkage.wgsl`) through a paint callback.
//!
//! Two implementations of one [`Renderer`], chosen when building: wgpu (native, and
//! the web demo's WebGPU build) and WebGL2 through glow (the web demo's other build,
//! with the GLSL naga translated from the same WGSL, `shaders/gl/`).

pub mod build;
mod cam_shapes;
pub mod drawing_shapes;
mod drawn;
pub mod gear_pair_shapes;
pub mod gear_shapes;
pub mod shape;
pub mod train_shapes;
pub mod view;

#[cfg(all(target_arch = "wasm32", feature = "webgl", not(feature = "webgpu")))]
mod gl_pipeline;
#[cfg(any(not(target_arch = "wasm32"), feature = "webgpu"))]
mod wgpu_pipeline;

#[cfg(all(target_arch = "wasm32", feature = "webgl", not(feature = "webgpu")))]
pub use gl_pipeline::Renderer;
#[cfg(any(not(target_arch = "wasm32"), feature = "webgpu"))]
pub use wgpu_pipeline::Renderer;

#[cfg(all(
    target_arch = "wasm32",
    not(feature = "webgl"),
    not(feature = "webgpu")
))]
compile_error!(
    "the web build draws with WebGPU or WebGL2: build with --features webgpu or \
     --features webgl (scripts/build_web.sh builds both)"
);
