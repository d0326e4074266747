//! The wgpu side: the pipeline over `shaders/linkage.wgsl`, kept in egui-wgpu's
//! callback resources, and the paint callback that uploads the frame's shapes in
//! `prepare` and draws them in `paint`.

use std::sync::{Arc, Mutex};

use eframe::egui_wgpu::{self, wgpu};

use super::shape::{ATTRIBUTES, Shape, ViewUniform};

/// Instances the buffer holds at first; it doubles when a frame needs more.
const INITIAL_CAPACITY: usize = 4096;

/// The shapes of the frame, written by the app and read by the callback (shared, so
/// that no per-frame copy of the list is made).
pub type SharedShapes = Arc<Mutex<Vec<Shape>>>;

/// GPU resources, created once per wgpu device.
pub struct MechanismPipeline {
    pipeline: wgpu::RenderPipeline,
    uniform: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    instances: wgpu::Buffer,
    capacity: usize,
    count: u32,
}

impl MechanismPipeline {
    /// Builds the pipeline for `render_state`'s target and stores it in its callback
    /// resources.
    pub fn install(render_state: &egui_wgpu::RenderState) {
        let device = &render_state.device;
        let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("linkage shapes"),
            source: wgpu::ShaderSource::Wgsl(include_str!("../../shaders/linkage.wgsl").into()),
        });
        let bind_group_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("linkage view"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: None,
                },
                count: None,
            }],
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("linkage shapes"),
            bind_group_layouts: &[Some(&bind_group_layout)],
            immediate_size: 0,
        });
        let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("linkage shapes"),
            layout: Some(&layout),
            vertex: wgpu::VertexState {
                module: &shader,
                entry_point: Some("vs_main"),
                compilation_options: Default::default(),
                buffers: &[Some(wgpu::VertexBufferLayout {
                    array_stride: std::mem::size_of::<Shape>() as u64,
                    step_mode: wgpu::VertexStepMode::Instance,
                    attributes: &ATTRIBUTES,
                })],
            },
            fragment: Some(wgpu::FragmentState {
                module: &shader,
                entry_point: Some("fs_main"),
                compilation_options: Default::default(),
                targets: &[Some(wgpu::ColorTargetState {
                    format: render_state.target_format,
                    blend: Some(wgpu::BlendState::PREMULTIPLIED_ALPHA_BLENDING),
                    write_mask: wgpu::ColorWrites::ALL,
                })],
            }),
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: None,
            // egui's own pass is single-sampled (eframe's default).
            multisample: wgpu::MultisampleState::default(),
            multiview_mask: None,
            cache: None,
        });
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("linkage view"),
            size: std::mem::size_of::<ViewUniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("linkage view"),
            layout: &bind_group_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: uniform.as_entire_binding(),
            }],
        });
        let instances = instance_buffer(device, INITIAL_CAPACITY);
        render_state
            .renderer
            .write()
            .callback_resources
            .insert(Self {
                pipeline,
                uniform,
                bind_group,
                instances,
                capacity: INITIAL_CAPACITY,
                count: 0,
            });
    }
}

fn instance_buffer(device: &wgpu::Device, capacity: usize) -> wgpu::Buffer {
    device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("linkage shapes"),
        size: (capacity * std::mem::size_of::<Shape>()) as u64,
        usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    })
}

/// This frame's draw: the view transform and the shared shape list.
pub struct MechanismCallback {
    /// The view transform.
    pub view: ViewUniform,
    /// The shapes, in drawing order.
    pub shapes: SharedShapes,
}

impl egui_wgpu::CallbackTrait for MechanismCallback {
    fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        _screen: &egui_wgpu::ScreenDescriptor,
        _encoder: &mut wgpu::CommandEncoder,
        resources: &mut egui_wgpu::CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        let Some(gpu) = resources.get_mut::<MechanismPipeline>() else {
            return Vec::new();
        };
        // A poisoned lock only means a panic elsewhere mid-write: draw nothing then.
        let Ok(shapes) = self.shapes.lock() else {
            gpu.count = 0;
            return Vec::new();
        };
        gpu.count = 0;
        if shapes.is_empty() {
            return Vec::new();
        }
        if shapes.len() > gpu.capacity {
            gpu.capacity = shapes.len().next_power_of_two();
            gpu.instances = instance_buffer(device, gpu.capacity);
        }
        queue.write_buffer(&gpu.uniform, 0, bytemuck::bytes_of(&self.view));
        queue.write_buffer(&gpu.instances, 0, bytemuck::cast_slice(&shapes));
        gpu.count = shapes.len() as u32;
        Vec::new()
    }

    fn paint(
        &self,
        _info: eframe::egui::PaintCallbackInfo,
        pass: &mut wgpu::RenderPass<'static>,
        resources: &egui_wgpu::CallbackResources,
    ) {
        let Some(gpu) = resources.get::<MechanismPipeline>() else {
            return;
        };
        if gpu.count == 0 {
            return;
        }
        pass.set_pipeline(&gpu.pipeline);
        pass.set_bind_group(0, &gpu.bind_group, &[]);
        pass.set_vertex_buffer(0, gpu.instances.slice(..));
        pass.draw(0..6, 0..gpu.count);
    }
}
