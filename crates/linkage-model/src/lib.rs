//! The app's model, free of any GUI type: the open document with its pose and
//! analyses ([`session`]), the user's drawing ([`drawing`]), the shipped scenes and
//! templates ([`catalog`]), and the synthesis tabs' inputs and designs with the
//! searches that run off the frame. It depends on the solver and the diagram crate,
//! not on egui or wgpu, so the compiler keeps it so; its tests and the edit
//! benchmark build without a renderer.

pub mod catalog;
pub mod drawing;
pub mod exercise;
pub mod job;
pub mod session;
pub mod synthesis;
