//! The WebGL2 renderer (the web demo's build for browsers without WebGPU): the same
//! instanced draw as the wgpu one, through eframe's glow painter, with the GLSL ES
//! 3.00 that naga translated from `shaders/linkage.wgsl` (`shaders/gl/`, kept equal
//! to the translation by `tests/app/gl_shaders.rs`).
//!
//! Why glow here and not wgpu's own WebGL2 back-end: that one carries wgpu-core and
//! naga into the download (0.5 MB gzipped, a quarter of it), to translate at run time
//! the one shader that can be translated when building.

// glow marks every GL call unsafe (natively they are FFI). In the browser they are
// WebGL calls through wasm-bindgen; what they need is a current context (the one egui
// paints with) and objects made on it, which this file keeps to.
#![allow(unsafe_code)]

use std::sync::{Arc, Mutex};

use eframe::egui;
use eframe::egui_glow;
use eframe::glow::{self, HasContext};

use super::shape::{Shape, SharedShapes, ViewUniform};

const VERTEX_SHADER: &str = include_str!("../../shaders/gl/linkage.vert");
const FRAGMENT_SHADER: &str = include_str!("../../shaders/gl/linkage.frag");

/// Instances the buffer holds at first; it doubles when a frame needs more.
const INITIAL_CAPACITY: usize = 4096;

/// The mechanism view's renderer: GL objects made once on egui's context.
pub struct Renderer {
    objects: Arc<Mutex<GlObjects>>,
}

impl Renderer {
    /// Compiles the shaders and makes the buffers on eframe's GL context, or `None`
    /// (logged) where there is none or the browser refuses them.
    pub fn install(cc: &eframe::CreationContext<'_>) -> Option<Self> {
        let gl = cc.gl.as_ref()?;
        // SAFETY: `gl` is the context egui paints with, current on this thread.
        match unsafe { GlObjects::new(gl) } {
            Ok(objects) => Some(Self {
                objects: Arc::new(Mutex::new(objects)),
            }),
            Err(why) => {
                log::error!("the WebGL2 mechanism renderer could not start: {why}");
                None
            }
        }
    }

    /// The paint callback that draws `shapes` into `rect` with `view`.
    pub fn paint_callback(
        &self,
        rect: egui::Rect,
        view: ViewUniform,
        shapes: &SharedShapes,
    ) -> egui::PaintCallback {
        let objects = self.objects.clone();
        let shapes = shapes.clone();
        let draw = move |_info: egui::PaintCallbackInfo, painter: &egui_glow::Painter| {
            // A poisoned lock only means a panic elsewhere mid-write: draw nothing then.
            let (Ok(mut objects), Ok(shapes)) = (objects.lock(), shapes.lock()) else {
                return;
            };
            // SAFETY: egui_glow calls this with its own context current, the viewport
            // set to `rect`, and restores its state afterwards.
            unsafe { objects.draw(painter.gl(), &view, &shapes) };
        };
        egui::PaintCallback {
            rect,
            callback: Arc::new(egui_glow::CallbackFn::new(draw)),
        }
    }
}

/// The program, the vertex array over the instance buffer, and the view's uniform
/// buffer.
struct GlObjects {
    program: glow::Program,
    vertex_array: glow::VertexArray,
    instances: glow::Buffer,
    uniform: glow::Buffer,
    capacity: usize,
}

impl GlObjects {
    /// # Safety
    /// `gl` must be current.
    unsafe fn new(gl: &glow::Context) -> Result<Self, String> {
        let program = unsafe { link_program(gl)? };
        let uniform = unsafe { gl.create_buffer()? };
        unsafe {
            gl.bind_buffer(glow::UNIFORM_BUFFER, Some(uniform));
            gl.buffer_data_size(
                glow::UNIFORM_BUFFER,
                std::mem::size_of::<ViewUniform>() as i32,
                glow::DYNAMIC_DRAW,
            );
            gl.bind_buffer(glow::UNIFORM_BUFFER, None);
        }
        let vertex_array = unsafe { gl.create_vertex_array()? };
        let instances = unsafe { gl.create_buffer()? };
        unsafe {
            gl.bind_vertex_array(Some(vertex_array));
            gl.bind_buffer(glow::ARRAY_BUFFER, Some(instances));
            gl.buffer_data_size(
                glow::ARRAY_BUFFER,
                (INITIAL_CAPACITY * std::mem::size_of::<Shape>()) as i32,
                glow::DYNAMIC_DRAW,
            );
            describe_instances(gl);
            gl.bind_vertex_array(None);
            gl.bind_buffer(glow::ARRAY_BUFFER, None);
        }
        Ok(Self {
            program,
            vertex_array,
            instances,
            uniform,
            capacity: INITIAL_CAPACITY,
        })
    }

    /// Uploads the frame's shapes and view, and draws six vertices per shape.
    ///
    /// # Safety
    /// `gl` must be the context these objects were made on, current.
    unsafe fn draw(&mut self, gl: &glow::Context, view: &ViewUniform, shapes: &[Shape]) {
        if shapes.is_empty() {
            return;
        }
        unsafe {
            gl.bind_vertex_array(Some(self.vertex_array));
            gl.bind_buffer(glow::ARRAY_BUFFER, Some(self.instances));
            if shapes.len() > self.capacity {
                self.capacity = shapes.len().next_power_of_two();
                let bytes = self.capacity * std::mem::size_of::<Shape>();
                gl.buffer_data_size(glow::ARRAY_BUFFER, bytes as i32, glow::DYNAMIC_DRAW);
            }
            gl.buffer_sub_data_u8_slice(glow::ARRAY_BUFFER, 0, bytemuck::cast_slice(shapes));
            gl.bind_buffer(glow::UNIFORM_BUFFER, Some(self.uniform));
            gl.buffer_sub_data_u8_slice(glow::UNIFORM_BUFFER, 0, bytemuck::bytes_of(view));
            gl.bind_buffer_base(glow::UNIFORM_BUFFER, 0, Some(self.uniform));
            gl.use_program(Some(self.program));
            // Premultiplied alpha, as egui and the wgpu pipeline blend.
            gl.enable(glow::BLEND);
            gl.blend_equation(glow::FUNC_ADD);
            gl.blend_func(glow::ONE, glow::ONE_MINUS_SRC_ALPHA);
            gl.draw_arrays_instanced(glow::TRIANGLES, 0, 6, shapes.len() as i32);
            gl.bind_vertex_array(None);
            gl.bind_buffer(glow::UNIFORM_BUFFER, None);
        }
    }
}

/// Compiles both stages and links them; every uniform block is bound to binding 0.
///
/// # Safety
/// `gl` must be current.
unsafe fn link_program(gl: &glow::Context) -> Result<glow::Program, String> {
    let program = unsafe { gl.create_program()? };
    let mut shaders = Vec::new();
    for (stage, source) in [
        (glow::VERTEX_SHADER, VERTEX_SHADER),
        (glow::FRAGMENT_SHADER, FRAGMENT_SHADER),
    ] {
        let shader = unsafe { gl.create_shader(stage)? };
        unsafe {
            gl.shader_source(shader, source);
            gl.compile_shader(shader);
            if !gl.get_shader_compile_status(shader) {
                return Err(format!("shader: {}", gl.get_shader_info_log(shader)));
            }
            gl.attach_shader(program, shader);
        }
        shaders.push(shader);
    }
    unsafe {
        gl.link_program(program);
        if !gl.get_program_link_status(program) {
            return Err(format!("program: {}", gl.get_program_info_log(program)));
        }
        for shader in shaders {
            gl.detach_shader(program, shader);
            gl.delete_shader(shader);
        }
        // naga names the view's block once per stage (`View_block_0Vertex`, ...):
        // each reads the one buffer at binding 0.
        let blocks = gl.get_program_parameter_i32(program, glow::ACTIVE_UNIFORM_BLOCKS);
        for block in 0..blocks.max(0) as u32 {
            gl.uniform_block_binding(program, block, 0);
        }
    }
    Ok(program)
}

/// The instance attributes of [`Shape`] at locations 0..=6, as the translated vertex
/// shader declares them (`layout(location = N)`), one step per instance.
///
/// # Safety
/// `gl` must be current, with the vertex array and the instance buffer bound.
unsafe fn describe_instances(gl: &glow::Context) {
    use std::mem::offset_of;
    let stride = std::mem::size_of::<Shape>() as i32;
    let floats = [
        (0, 2, offset_of!(Shape, p0)),
        (1, 2, offset_of!(Shape, p1)),
        (2, 2, offset_of!(Shape, p2)),
        (3, 1, offset_of!(Shape, radius)),
        (5, 4, offset_of!(Shape, color)),
        (6, 2, offset_of!(Shape, param)),
    ];
    unsafe {
        for (location, size, offset) in floats {
            gl.enable_vertex_attrib_array(location);
            gl.vertex_attrib_pointer_f32(location, size, glow::FLOAT, false, stride, offset as i32);
            gl.vertex_attrib_divisor(location, 1);
        }
        // The shape's kind is a `uint` attribute: integer, not normalised.
        let kind = 4;
        gl.enable_vertex_attrib_array(kind);
        gl.vertex_attrib_pointer_i32(
            kind,
            1,
            glow::UNSIGNED_INT,
            stride,
            offset_of!(Shape, kind) as i32,
        );
        gl.vertex_attrib_divisor(kind, 1);
    }
}
