//! The mechanism view's GPU renderer: one instanced draw of signed-distance shapes
//! (`shaders/linkage.wgsl`) through an egui-wgpu paint callback.

pub mod build;
pub mod pipeline;
pub mod shape;
pub mod view;
