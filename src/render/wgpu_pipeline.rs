//! The wgpu renderer (native, and the web demo's WebGPU build): the pipeline over
//! `shaders/linkage.wgsl`, kept in egui-wgpu's callback resources, and the paint
//! callback that uploads the frame's shapes in `prepare` and draws them in `paint`.

use eframe::egui;
use eframe::egui_wgpu::{self, wgpu};

use super::shape::{Shape, SharedShapes, ViewUniform};

/// Instances the buffer holds at first; it doubles when a frame needs more.
const INITIAL_CAPACITY: usize = 4096;

/// The vertex buffer layout of [`Shape`] as per-instance attributes 0..=6 (`Instance`
/// in the WGSL).
const ATTRIBUTES: [wgpu::VertexAttribute; 7] = wgpu::vertex_attr_array![
    0 => Float32x2, 1 => Float32x2, 2 => Float32x2, 3 => Float32, 4 => Uint32, 5 => Float32x4, 6 => Float32x2
];

/// The mechanism view's renderer; its GPU resources live in egui-wgpu's callback
/// resources.
pub struct Renderer;

impl Renderer {
    /// Builds the pipeline on the app's wgpu device, or `None` where eframe runs
    /// without one (the view then says so).
    pub fn install(cc: &eframe::CreationContext<'_>) -> Option<Self> {
        let render_state = cc.wgpu_render_state.as_ref()?;
        MechanismPipeline::install(render_state);
        Some(Self)
    }

    /// The paint callback that draws `shapes` into `rect` with `view`.
    pub fn paint_callback(
        &self,
        rect: egui::Rect,
        view: ViewUniform,
        shapes: &SharedShapes,
    ) -> egui::PaintCallback {
        egui_wgpu::Callback::new_paint_callback(
            rect,
            MechanismCallback {
                view,
                shapes: shapes.clone(),
            },
        )
    }
}

/// GPU resources, created once per wgpu device.
struct MechanismPipeline {
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
    fn install(render_state: &egui_wgpu::RenderState) {
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
struct MechanismCallback {
    /// The view transform.
    view: ViewUniform,
    /// The shapes, in drawing order.
    shapes: SharedShapes,
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shape_matches_the_wgsl_instance_layout() {
        // 3 vec2 + f32 + u32 + vec4 + vec2, tightly packed as the attributes say.
        assert_eq!(std::mem::size_of::<Shape>(), 56);
        assert_eq!(ATTRIBUTES[6].offset, 48);
        assert_eq!(
            ATTRIBUTES[6].offset,
            std::mem::offset_of!(Shape, param) as u64
        );
    }
}
