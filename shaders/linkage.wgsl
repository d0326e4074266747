// Linkage Lab: every mechanism shape as one instanced quad whose fragment shader
// evaluates the shape's signed distance, so edges are anti-aliased at any zoom
// without tessellation. Positions arrive relative to the view centre (subtracted in
// f64 on the CPU, so that huge coordinates keep their precision).

struct View {
    // Clip units per metre, x and y (y up in both).
    clip_per_m: vec2<f32>,
    // Metres per physical pixel: the anti-aliasing width.
    m_per_px: f32,
    _pad: f32,
};

@group(0) @binding(0) var<uniform> view: View;

// Shape kinds; keep in step with `render::shape::Kind`.
const BAR: u32 = 0u;
const PLATE: u32 = 1u;
const PIN: u32 = 2u;
const GROUND: u32 = 3u;
const BLOCK: u32 = 4u;
const SPRING: u32 = 5u;
const ARROW: u32 = 6u;
const LINE: u32 = 7u;
const DASH: u32 = 8u;
const FILL: u32 = 9u;

struct Instance {
    @location(0) p0: vec2<f32>,
    @location(1) p1: vec2<f32>,
    @location(2) p2: vec2<f32>,
    @location(3) radius: f32,
    @location(4) kind: u32,
    @location(5) color: vec4<f32>,
    @location(6) param: vec2<f32>,
};

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec2<f32>,
    @location(1) @interpolate(flat) p0: vec2<f32>,
    @location(2) @interpolate(flat) p1: vec2<f32>,
    @location(3) @interpolate(flat) p2: vec2<f32>,
    @location(4) @interpolate(flat) radius: f32,
    @location(5) @interpolate(flat) kind: u32,
    @location(6) @interpolate(flat) color: vec4<f32>,
    @location(7) @interpolate(flat) param: vec2<f32>,
};

// The quad's reach beyond p0..p2: what each kind draws outside its points.
fn reach(inst: Instance) -> f32 {
    var r = inst.radius;
    if inst.kind == GROUND {
        r = r + inst.param.x;
    } else if inst.kind == BLOCK {
        r = r + length(inst.param);
    } else if inst.kind == SPRING {
        r = r + inst.param.y;
    } else if inst.kind == ARROW {
        r = r + inst.param.x;
    }
    return r + 2.0 * view.m_per_px;
}

@vertex
fn vs_main(@builtin(vertex_index) vi: u32, inst: Instance) -> VertexOut {
    let lo = min(min(inst.p0, inst.p1), inst.p2) - vec2<f32>(reach(inst));
    let hi = max(max(inst.p0, inst.p1), inst.p2) + vec2<f32>(reach(inst));
    // Two triangles: corners 0,1,2 and 2,1,3 of the box.
    var corners = array<vec2<f32>, 6>(
        vec2<f32>(0.0, 0.0), vec2<f32>(1.0, 0.0), vec2<f32>(0.0, 1.0),
        vec2<f32>(0.0, 1.0), vec2<f32>(1.0, 0.0), vec2<f32>(1.0, 1.0),
    );
    let world = mix(lo, hi, corners[vi]);
    var out: VertexOut;
    out.clip = vec4<f32>(world * view.clip_per_m, 0.0, 1.0);
    out.world = world;
    out.p0 = inst.p0;
    out.p1 = inst.p1;
    out.p2 = inst.p2;
    out.radius = inst.radius;
    out.kind = inst.kind;
    out.color = inst.color;
    out.param = inst.param;
    return out;
}

// Distance to the segment a-b, and the position along it in [0, 1].
fn segment(p: vec2<f32>, a: vec2<f32>, b: vec2<f32>) -> vec2<f32> {
    let ab = b - a;
    let h = clamp(dot(p - a, ab) / max(dot(ab, ab), 1e-30), 0.0, 1.0);
    return vec2<f32>(length(p - a - ab * h), h);
}

// Signed distance to the triangle a, b, c (negative inside).
fn triangle(p: vec2<f32>, a: vec2<f32>, b: vec2<f32>, c: vec2<f32>) -> f32 {
    let d = min(min(segment(p, a, b).x, segment(p, b, c).x), segment(p, c, a).x);
    let s0 = sign((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x));
    let s1 = sign((c.x - b.x) * (p.y - b.y) - (c.y - b.y) * (p.x - b.x));
    let s2 = sign((a.x - c.x) * (p.y - c.y) - (a.y - c.y) * (p.x - c.x));
    let inside = (s0 >= 0.0 && s1 >= 0.0 && s2 >= 0.0) || (s0 <= 0.0 && s1 <= 0.0 && s2 <= 0.0);
    return select(d, -d, inside);
}

// Signed distance to a box centred at c with unit axis u and half sizes h.
fn oriented_box(p: vec2<f32>, c: vec2<f32>, u: vec2<f32>, h: vec2<f32>) -> f32 {
    let d = p - c;
    let local = vec2<f32>(dot(d, u), dot(d, vec2<f32>(-u.y, u.x)));
    let q = abs(local) - h;
    return length(max(q, vec2<f32>(0.0))) + min(max(q.x, q.y), 0.0);
}

// Coverage of a shape with signed distance d (one pixel of smooth edge).
fn coverage(d: f32) -> f32 {
    return clamp(0.5 - d / view.m_per_px, 0.0, 1.0);
}

// Fill with a darker outline of `border` metres.
fn outlined(d: f32, border: f32, fill: vec4<f32>) -> vec4<f32> {
    let edge = vec4<f32>(fill.rgb * 0.45, fill.a);
    let inner = coverage(d + border);
    let rgb = mix(edge.rgb, fill.rgb, inner);
    return vec4<f32>(rgb, coverage(d));
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    let p = in.world;
    let px = view.m_per_px;
    var colour = in.color;
    var alpha = 0.0;
    if in.kind == BAR {
        let d = segment(p, in.p0, in.p1).x - in.radius;
        let c = outlined(d, 1.5 * px, colour);
        colour = c;
        alpha = c.a;
    } else if in.kind == PLATE {
        let d = triangle(p, in.p0, in.p1, in.p2) - in.radius;
        let c = outlined(d, 1.5 * px, colour);
        colour = c;
        alpha = c.a;
    } else if in.kind == PIN {
        // A white pin with a dark ring and a dark centre dot.
        let r = length(p - in.p0);
        let ring = abs(r - in.radius * 0.8) - in.radius * 0.2;
        let dot_d = r - in.radius * 0.25;
        let dark = max(coverage(ring), coverage(dot_d));
        let rgb = mix(vec3<f32>(0.97, 0.97, 0.95), colour.rgb, dark);
        colour = vec4<f32>(rgb, 1.0);
        alpha = coverage(r - in.radius);
    } else if in.kind == GROUND {
        // Base line p1-p2 with hatching below it, param.x deep.
        let axis = normalize(in.p2 - in.p1);
        let normal = vec2<f32>(axis.y, -axis.x);
        let mid = 0.5 * (in.p1 + in.p2);
        let half_len = 0.5 * length(in.p2 - in.p1);
        let line = segment(p, in.p1, in.p2).x - in.radius;
        let depth = in.param.x;
        let inside = oriented_box(p, mid + normal * depth * 0.5, axis, vec2<f32>(half_len, depth * 0.5));
        let u = dot(p - mid, axis);
        let v = dot(p - mid, normal);
        let spacing = max(depth * 0.45, 2.0 * px);
        let stripe = abs(fract((u + v) / spacing) - 0.5) * spacing - 0.6 * px;
        // Hatching fades away from the line, as drawn by hand.
        let fade = clamp(1.0 - v / depth, 0.0, 1.0);
        let hatch = coverage(max(inside, stripe)) * fade;
        alpha = max(coverage(line), hatch);
    } else if in.kind == BLOCK {
        let axis = normalize(in.p1 - in.p0);
        let d = oriented_box(p, in.p0, axis, in.param) - in.radius;
        let c = outlined(d, 1.5 * px, colour);
        colour = c;
        alpha = c.a;
    } else if in.kind == SPRING {
        // A zigzag coil of param.x turns and param.y amplitude between p0 and p1, with
        // straight leads of a tenth of the length at each end.
        let l = max(length(in.p1 - in.p0), 1e-20);
        let axis = (in.p1 - in.p0) / l;
        let normal = vec2<f32>(-axis.y, axis.x);
        let u = dot(p - in.p0, axis);
        let v = dot(p - in.p0, normal);
        let lead = 0.1 * l;
        let coil_len = l - 2.0 * lead;
        let turns = max(in.param.x, 1.0);
        let amp = in.param.y;
        let t = clamp((u - lead) / max(coil_len, 1e-20), 0.0, 1.0) * turns;
        let tri = amp * (4.0 * abs(fract(t + 0.25) - 0.5) - 1.0);
        let slope = 4.0 * amp * turns / max(coil_len, 1e-20);
        var d = abs(v - tri) / sqrt(1.0 + slope * slope) - in.radius;
        if u < lead || u > l - lead {
            d = segment(p, in.p0, in.p1).x - in.radius;
            if u >= lead - in.radius && u <= l - lead + in.radius {
                d = min(d, abs(v - tri) - in.radius);
            }
        }
        alpha = coverage(d);
    } else if in.kind == ARROW {
        // Shaft p0->p1 and a head of length param.x.
        let l = length(in.p1 - in.p0);
        let axis = (in.p1 - in.p0) / max(l, 1e-30);
        let normal = vec2<f32>(-axis.y, axis.x);
        let head = min(in.param.x, l);
        let base = in.p1 - axis * head;
        let shaft = segment(p, in.p0, base).x - in.radius;
        let tip = triangle(p, in.p1, base + normal * head * 0.4, base - normal * head * 0.4);
        alpha = coverage(min(shaft, tip));
    } else if in.kind == LINE {
        alpha = coverage(segment(p, in.p0, in.p1).x - in.radius);
    } else if in.kind == FILL {
        // A triangle of one flat colour without an outline: pieces of a larger area
        // (a cam's disc) that meet edge to edge.
        alpha = coverage(triangle(p, in.p0, in.p1, in.p2) - in.radius);
    } else if in.kind == DASH {
        // Dashes of param.x metres with equal gaps.
        let s = segment(p, in.p0, in.p1);
        let along = s.y * length(in.p1 - in.p0);
        let gap = abs(fract(along / (2.0 * in.param.x)) - 0.5) * 2.0 * in.param.x - 0.5 * in.param.x;
        alpha = coverage(max(s.x - in.radius, -gap));
    }
    let a = alpha * in.color.a;
    if a <= 0.002 {
        discard;
    }
    // egui blends premultiplied alpha.
    return vec4<f32>(colour.rgb * a, a);
}
