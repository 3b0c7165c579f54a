//! A scene drawn into pixels (tiny-skia, anti-aliased), map layers cell by cell.

use tiny_skia::{Color, FillRule, Paint, PathBuilder, Pixmap, Stroke as SkStroke, Transform};

use crate::scene::{Mark, Scene, Stroke};
use crate::{FigureError, GridImage, Rgba};

/// A drawn scene.
pub(crate) struct Raster {
    pub(crate) pixmap: Pixmap,
}

impl Raster {
    /// Straight (not premultiplied) RGBA bytes, top row first.
    pub(crate) fn to_rgba(&self) -> Vec<u8> {
        self.pixmap
            .pixels()
            .iter()
            .flat_map(|p| {
                let c = p.demultiply();
                [c.red(), c.green(), c.blue(), c.alpha()]
            })
            .collect()
    }
}

pub(crate) fn render(scene: &Scene) -> Result<Raster, FigureError> {
    let (w, h) = scene.size_px();
    let mut pixmap = Pixmap::new(w, h).ok_or(FigureError::TooLarge {
        path: crate::error::MEMORY.into(),
        width: w,
        height: h,
    })?;
    if let Some(bg) = scene.background {
        pixmap.fill(Color::from_rgba8(bg[0], bg[1], bg[2], bg[3]));
    }
    for mark in &scene.marks {
        draw(&mut pixmap, scene, mark);
    }
    Ok(Raster { pixmap })
}

fn draw(pixmap: &mut Pixmap, scene: &Scene, mark: &Mark) {
    let px = |p| {
        let q = scene.to_px(p);
        (q[0] as f32, q[1] as f32)
    };
    let mut pb = PathBuilder::new();
    match mark {
        Mark::Grid(grid) => grid_cells(pixmap, scene, grid),
        Mark::Segments { pairs, stroke } => {
            for (a, b) in pairs {
                let (a, b) = (px(*a), px(*b));
                pb.move_to(a.0, a.1);
                pb.line_to(b.0, b.1);
            }
            stroke_path(pixmap, pb, stroke);
        }
        Mark::Polyline { points, stroke, .. } => {
            for (k, p) in points.iter().enumerate() {
                let p = px(*p);
                if k == 0 {
                    pb.move_to(p.0, p.1);
                } else {
                    pb.line_to(p.0, p.1);
                }
            }
            stroke_path(pixmap, pb, stroke);
        }
        Mark::Disc {
            center,
            radius,
            fill,
            stroke,
        } => {
            let c = px(*center);
            let r = (radius * scene.px_per_unit()) as f32;
            if let Some(colour) = fill {
                let mut pb = PathBuilder::new();
                pb.push_circle(c.0, c.1, r);
                if let Some(path) = pb.finish() {
                    pixmap.fill_path(
                        &path,
                        &paint(*colour),
                        FillRule::Winding,
                        Transform::identity(),
                        None,
                    );
                }
            }
            if let Some(st) = stroke {
                pb.push_circle(c.0, c.1, r);
                stroke_path(pixmap, pb, st);
            }
        }
        Mark::Moving { frames, .. } => {
            if let Some(first) = frames.first() {
                draw(pixmap, scene, first);
            }
        }
    }
}

fn paint(c: Rgba) -> Paint<'static> {
    let mut paint = Paint::default();
    paint.set_color(Color::from_rgba8(c[0], c[1], c[2], c[3]));
    paint.anti_alias = true;
    paint
}

fn stroke_path(pixmap: &mut Pixmap, pb: PathBuilder, st: &Stroke) {
    let Some(path) = pb.finish() else { return };
    let mut s = SkStroke {
        width: st.width as f32,
        ..SkStroke::default()
    };
    if st.round {
        s.line_join = tiny_skia::LineJoin::Round;
    }
    if let Some([on, off]) = st.dash {
        s.dash = tiny_skia::StrokeDash::new(vec![on as f32, off as f32], 0.0);
    }
    pixmap.stroke_path(&path, &paint(st.colour), &s, Transform::identity(), None);
}

/// Each pixel of the layer's place takes the colour of the cell under its centre: cells
/// stay sharp squares, with no seams between rows.
fn grid_cells(pixmap: &mut Pixmap, scene: &Scene, grid: &GridImage) {
    let (pw, ph) = (pixmap.width() as usize, pixmap.height() as usize);
    let s = scene.px_per_unit();
    let r = grid.resolution();
    let o = grid.origin();
    let top = scene.to_px(hyplan_core::Point2::new(
        o.x,
        o.y + grid.height() as f64 * r,
    ));
    let (cell_w, cell_h) = (grid.width() as f64 * r * s, grid.height() as f64 * r * s);
    let x0 = top[0].max(0.0).floor() as usize;
    let y0 = top[1].max(0.0).floor() as usize;
    let x1 = ((top[0] + cell_w).ceil().max(0.0) as usize).min(pw);
    let y1 = ((top[1] + cell_h).ceil().max(0.0) as usize).min(ph);
    let cell_px = r * s;
    let data = pixmap.data_mut();
    for y in y0..y1 {
        let from_top = ((y as f64 + 0.5 - top[1]) / cell_px).floor();
        if from_top < 0.0 || from_top >= grid.height() as f64 {
            continue;
        }
        let j = grid.height() - 1 - from_top as usize;
        for x in x0..x1 {
            let i = ((x as f64 + 0.5 - top[0]) / cell_px).floor();
            if i < 0.0 || i >= grid.width() as f64 {
                continue;
            }
            let c = grid.colour(i as usize, j);
            let dst = &mut data[4 * (y * pw + x)..4 * (y * pw + x) + 4];
            blend(dst, c);
        }
    }
}

/// Source-over of a straight colour onto a premultiplied pixel.
fn blend(dst: &mut [u8], c: Rgba) {
    match c[3] {
        255 => dst.copy_from_slice(&c),
        0 => {}
        a => {
            let a = u32::from(a);
            for k in 0..3 {
                let src = u32::from(c[k]) * a / 255;
                dst[k] = (src + u32::from(dst[k]) * (255 - a) / 255) as u8;
            }
            dst[3] = (a + u32::from(dst[3]) * (255 - a) / 255) as u8;
        }
    }
}
