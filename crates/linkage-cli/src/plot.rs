//! The work–precision PNG: error against CPU time, log–log, one line per method.
//!
//! plotters draws the axes and the series into an RGB buffer; its text needs a
//! system font library (font-kit), so the labels are rasterised here with ab_glyph
//! from the font egui already ships, and the buffer is written with the png crate.
//! Nothing depends on the machine's fonts.

use std::path::Path;

use ab_glyph::{Font, FontRef, PxScale, ScaleFont, point};
use plotters::prelude::*;

use crate::error::{CliError, Result};

/// One line of the plot: a label and its (x, y) points.
pub struct Series {
    /// Legend text.
    pub label: String,
    /// Points, both coordinates > 0 (log axes).
    pub points: Vec<(f64, f64)>,
}

const WIDTH: u32 = 960;
const HEIGHT: u32 = 640;
const MARGIN_LEFT: u32 = 90;
const MARGIN_BOTTOM: u32 = 70;
const MARGIN_TOP: u32 = 50;
const MARGIN_RIGHT: u32 = 30;

/// Text to draw after plotters has finished: (x, y) of its left end / baseline.
struct Label {
    text: String,
    x: i32,
    y: i32,
    size: f32,
    color: (u8, u8, u8),
}

fn decades(lo: f64, hi: f64) -> (f64, f64) {
    (
        10f64.powf(lo.log10().floor()),
        10f64.powf(hi.log10().ceil()),
    )
}

/// The plotting library's or the PNG encoder's error, in its own words.
fn plot_error(e: impl std::fmt::Display) -> CliError {
    CliError::Plot(e.to_string())
}

/// Writes a log–log plot of `series` to `path`.
pub fn work_precision_png(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[Series],
) -> Result<()> {
    let all: Vec<(f64, f64)> = series
        .iter()
        .flat_map(|s| s.points.iter().copied())
        .filter(|(x, y)| *x > 0.0 && *y > 0.0 && x.is_finite() && y.is_finite())
        .collect();
    if all.is_empty() {
        return Err(CliError::refused(
            "nothing to plot: no point has a positive, finite error and time",
        ));
    }
    let fold = |f: fn(f64, f64) -> f64, start: f64, pick: fn(&(f64, f64)) -> f64| {
        all.iter().map(pick).fold(start, f)
    };
    let (x0, x1) = decades(
        fold(f64::min, f64::INFINITY, |p| p.0),
        fold(f64::max, 0.0, |p| p.0),
    );
    let (y0, y1) = decades(
        fold(f64::min, f64::INFINITY, |p| p.1),
        fold(f64::max, 0.0, |p| p.1),
    );
    let mut buffer = vec![255u8; (WIDTH * HEIGHT * 3) as usize];
    let mut labels = Vec::new();
    let colors = [
        RGBColor(31, 119, 180),
        RGBColor(255, 127, 14),
        RGBColor(44, 160, 44),
        RGBColor(214, 39, 40),
        RGBColor(148, 103, 189),
        RGBColor(140, 86, 75),
        RGBColor(227, 119, 194),
    ];
    {
        let root = BitMapBackend::with_buffer(&mut buffer, (WIDTH, HEIGHT)).into_drawing_area();
        let mut chart = ChartBuilder::on(&root)
            .margin_left(MARGIN_LEFT)
            .margin_bottom(MARGIN_BOTTOM)
            .margin_top(MARGIN_TOP)
            .margin_right(MARGIN_RIGHT)
            .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())
            .map_err(plot_error)?;
        chart
            .configure_mesh()
            .x_labels(0)
            .y_labels(0)
            .light_line_style(RGBColor(235, 235, 235))
            .draw()
            .map_err(plot_error)?;
        // Decade grid lines and tick labels (plotters' own labels need font-kit).
        let mut decade = x0;
        while decade <= x1 * 1.0001 {
            chart
                .draw_series(LineSeries::new(
                    [(decade, y0), (decade, y1)],
                    RGBColor(200, 200, 200),
                ))
                .map_err(plot_error)?;
            let (px, _) = chart.backend_coord(&(decade, y0));
            labels.push(Label {
                text: format!("1e{}", decade.log10().round()),
                x: px - 14,
                y: HEIGHT as i32 - MARGIN_BOTTOM as i32 + 22,
                size: 16.0,
                color: (60, 60, 60),
            });
            decade *= 10.0;
        }
        let mut decade = y0;
        while decade <= y1 * 1.0001 {
            chart
                .draw_series(LineSeries::new(
                    [(x0, decade), (x1, decade)],
                    RGBColor(200, 200, 200),
                ))
                .map_err(plot_error)?;
            let (_, py) = chart.backend_coord(&(x0, decade));
            labels.push(Label {
                text: format!("1e{}", decade.log10().round()),
                x: 30,
                y: py + 5,
                size: 16.0,
                color: (60, 60, 60),
            });
            decade *= 10.0;
        }
        for (i, s) in series.iter().enumerate() {
            let color = colors[i % colors.len()];
            let points: Vec<(f64, f64)> = s
                .points
                .iter()
                .copied()
                .filter(|(x, y)| *x > 0.0 && *y > 0.0 && x.is_finite() && y.is_finite())
                .collect();
            chart
                .draw_series(LineSeries::new(points.clone(), color.stroke_width(2)))
                .map_err(plot_error)?;
            chart
                .draw_series(points.iter().map(|&p| Circle::new(p, 4, color.filled())))
                .map_err(plot_error)?;
            // Legend: a swatch and the label, bottom left (cheap and exact: empty).
            let (lx, ly) = (
                MARGIN_LEFT as i32 + 20,
                HEIGHT as i32 - MARGIN_BOTTOM as i32 - 16 - 24 * (series.len() - 1 - i) as i32,
            );
            root.draw(&Rectangle::new(
                [(lx, ly - 8), (lx + 24, ly - 4)],
                color.filled(),
            ))
            .map_err(plot_error)?;
            labels.push(Label {
                text: s.label.clone(),
                x: lx + 32,
                y: ly,
                size: 17.0,
                color: (color.0, color.1, color.2),
            });
        }
        root.present().map_err(plot_error)?;
    }
    labels.push(Label {
        text: title.into(),
        x: MARGIN_LEFT as i32,
        y: 22,
        size: 20.0,
        color: (0, 0, 0),
    });
    labels.push(Label {
        text: x_label.into(),
        x: (WIDTH / 2) as i32 - 120,
        y: HEIGHT as i32 - 16,
        size: 18.0,
        color: (0, 0, 0),
    });
    labels.push(Label {
        text: y_label.into(),
        x: 8,
        y: MARGIN_TOP as i32 - 6,
        size: 16.0,
        color: (0, 0, 0),
    });
    let font = FontRef::try_from_slice(epaint_default_fonts::UBUNTU_LIGHT)
        .map_err(|e| CliError::Plot(format!("built-in font: {e}")))?;
    for label in &labels {
        draw_text(&mut buffer, &font, label);
    }
    write_png(path, &buffer)
}

/// Rasterises `label` into the RGB buffer with coverage blending.
fn draw_text(buffer: &mut [u8], font: &FontRef<'_>, label: &Label) {
    let scaled = font.as_scaled(PxScale::from(label.size));
    let mut caret = label.x as f32;
    let mut previous = None;
    for c in label.text.chars() {
        let id = scaled.glyph_id(c);
        if let Some(p) = previous {
            caret += scaled.kern(p, id);
        }
        let glyph = id.with_scale_and_position(label.size, point(caret, label.y as f32));
        caret += scaled.h_advance(id);
        previous = Some(id);
        let Some(outline) = font.outline_glyph(glyph) else {
            continue;
        };
        let bounds = outline.px_bounds();
        outline.draw(|gx, gy, coverage| {
            let x = bounds.min.x as i32 + gx as i32;
            let y = bounds.min.y as i32 + gy as i32;
            if x < 0 || y < 0 || x >= WIDTH as i32 || y >= HEIGHT as i32 {
                return;
            }
            let i = ((y as u32 * WIDTH + x as u32) * 3) as usize;
            let ink = [label.color.0, label.color.1, label.color.2];
            for (channel, &value) in buffer[i..i + 3].iter_mut().zip(&ink) {
                let old = f32::from(*channel);
                *channel = (old + (f32::from(value) - old) * coverage).round() as u8;
            }
        });
    }
}

fn write_png(path: &Path, rgb: &[u8]) -> Result<()> {
    let file = std::fs::File::create(path).map_err(|e| CliError::in_file(path, plot_error(e)))?;
    let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), WIDTH, HEIGHT);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder
        .write_header()
        .map_err(|e| CliError::in_file(path, plot_error(e)))?;
    writer
        .write_image_data(rgb)
        .map_err(|e| CliError::in_file(path, plot_error(e)))
}
