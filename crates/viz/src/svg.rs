//! A scene as SVG text, in pixels (y down), marks in the scene's order.

use std::fmt::Write as _;

use base64::Engine as _;

use crate::scene::{Mark, Scene, Stroke};
use crate::{FigureError, GridImage, hex};

/// The SVG document of a scene.
pub(crate) fn write(scene: &Scene) -> Result<String, FigureError> {
    let (w, h) = scene.size_px();
    let mut s = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}">"#
    );
    s.push('\n');
    if let Some(bg) = scene.background {
        let _ = writeln!(
            s,
            r#"<rect width="{w}" height="{h}" fill="{}"{}/>"#,
            hex(bg),
            alpha_attr("fill-opacity", bg[3])
        );
    }
    for mark in &scene.marks {
        mark_svg(&mut s, scene, mark)?;
    }
    s.push_str("</svg>\n");
    Ok(s)
}

fn mark_svg(s: &mut String, scene: &Scene, mark: &Mark) -> Result<(), FigureError> {
    let px = |p| scene.to_px(p);
    match mark {
        Mark::Grid(grid) => grid_svg(s, scene, grid)?,
        Mark::Segments { pairs, stroke } => {
            let mut d = String::new();
            for (a, b) in pairs {
                let (a, b) = (px(*a), px(*b));
                let _ = write!(d, "M{:.2} {:.2}L{:.2} {:.2}", a[0], a[1], b[0], b[1]);
            }
            let _ = writeln!(s, r#"<path d="{d}" fill="none"{}/>"#, stroke_attrs(stroke));
        }
        Mark::Polyline {
            points,
            stroke,
            title,
        } => {
            let mut d = String::new();
            for (k, p) in points.iter().enumerate() {
                let p = px(*p);
                let _ = write!(
                    d,
                    "{}{:.2} {:.2}",
                    if k == 0 { 'M' } else { 'L' },
                    p[0],
                    p[1]
                );
            }
            let attrs = format!(r#"d="{d}" fill="none"{}"#, stroke_attrs(stroke));
            match title {
                Some(t) => {
                    let _ = writeln!(s, "<path {attrs}><title>{}</title></path>", escape(t));
                }
                None => {
                    let _ = writeln!(s, "<path {attrs}/>");
                }
            }
        }
        Mark::Disc {
            center,
            radius,
            fill,
            stroke,
        } => {
            let c = px(*center);
            let _ = writeln!(
                s,
                r#"<circle cx="{:.2}" cy="{:.2}" r="{:.2}"{}/>"#,
                c[0],
                c[1],
                radius * scene.px_per_unit(),
                disc_attrs(*fill, stroke.as_ref())
            );
        }
        Mark::Moving { times, frames } => moving_svg(s, scene, times, frames),
    }
    Ok(())
}

/// A map layer: the grid as a PNG at a whole number of pixels per cell (close to the
/// figure's), stretched to its place; viewers that honour `image-rendering` keep cells
/// square at any zoom.
fn grid_svg(s: &mut String, scene: &Scene, grid: &GridImage) -> Result<(), FigureError> {
    let cell_px = grid.resolution() * scene.px_per_unit();
    // A hair above the product: 0.05 m cells at 1200 px/m are 60 px, not 59.999.
    let scale = (cell_px + 1e-9).floor().max(1.0) as usize;
    let png = grid.png_bytes(scale)?;
    let o = grid.origin();
    let top_left = scene.to_px(hyplan_core::Point2::new(
        o.x,
        o.y + grid.height() as f64 * grid.resolution(),
    ));
    let _ = writeln!(
        s,
        r#"<image x="{:.2}" y="{:.2}" width="{:.2}" height="{:.2}" preserveAspectRatio="none" image-rendering="optimizeSpeed" style="image-rendering:pixelated" href="data:image/png;base64,{}"/>"#,
        top_left[0],
        top_left[1],
        grid.width() as f64 * cell_px,
        grid.height() as f64 * cell_px,
        base64::engine::general_purpose::STANDARD.encode(png)
    );
    Ok(())
}

/// A moving disc animates its centre, a moving segment its end points (SMIL, looping).
fn moving_svg(s: &mut String, scene: &Scene, times: &[f64], frames: &[Mark]) {
    let end = times.last().copied().unwrap_or(0.0).max(1e-3);
    let key_times = times
        .iter()
        .map(|t| format!("{:.4}", (t / end).clamp(0.0, 1.0)))
        .collect::<Vec<_>>()
        .join(";");
    let anim = |attr: &str, values: Vec<f64>| {
        let values = values
            .iter()
            .map(|v| format!("{v:.2}"))
            .collect::<Vec<_>>()
            .join(";");
        format!(
            r#"<animate attributeName="{attr}" dur="{end:.2}s" repeatCount="indefinite" calcMode="linear" keyTimes="{key_times}" values="{values}"/>"#
        )
    };
    let px = |p| scene.to_px(p);
    match frames.first() {
        Some(Mark::Disc {
            radius,
            fill,
            stroke,
            ..
        }) => {
            let centres: Vec<[f64; 2]> = frames
                .iter()
                .filter_map(|m| match m {
                    Mark::Disc { center, .. } => Some(px(*center)),
                    _ => None,
                })
                .collect();
            let _ = writeln!(
                s,
                r#"<circle r="{:.2}"{}>{}{}</circle>"#,
                radius * scene.px_per_unit(),
                disc_attrs(*fill, stroke.as_ref()),
                anim("cx", centres.iter().map(|c| c[0]).collect()),
                anim("cy", centres.iter().map(|c| c[1]).collect())
            );
        }
        Some(Mark::Segments { stroke, .. }) => {
            let ends: Vec<([f64; 2], [f64; 2])> = frames
                .iter()
                .filter_map(|m| match m {
                    Mark::Segments { pairs, .. } => pairs.first().map(|(a, b)| (px(*a), px(*b))),
                    _ => None,
                })
                .collect();
            let _ = writeln!(
                s,
                "<line{}>{}{}{}{}</line>",
                stroke_attrs(stroke),
                anim("x1", ends.iter().map(|e| e.0[0]).collect()),
                anim("y1", ends.iter().map(|e| e.0[1]).collect()),
                anim("x2", ends.iter().map(|e| e.1[0]).collect()),
                anim("y2", ends.iter().map(|e| e.1[1]).collect())
            );
        }
        // Other marks do not move in SVG: drawn still at their first frame.
        Some(other) => {
            let _ = mark_svg(s, scene, other);
        }
        None => {}
    }
}

fn alpha_attr(name: &str, a: u8) -> String {
    if a == 255 {
        String::new()
    } else {
        format!(r#" {name}="{:.3}""#, f64::from(a) / 255.0)
    }
}

fn stroke_attrs(st: &Stroke) -> String {
    let mut a = format!(
        r#" stroke="{}" stroke-width="{:.2}"{}"#,
        hex(st.colour),
        st.width,
        alpha_attr("stroke-opacity", st.colour[3])
    );
    if let Some([on, off]) = st.dash {
        let _ = write!(a, r#" stroke-dasharray="{on:.2} {off:.2}""#);
    }
    if st.round {
        a.push_str(r#" stroke-linejoin="round""#);
    }
    a
}

fn disc_attrs(fill: Option<crate::Rgba>, stroke: Option<&Stroke>) -> String {
    let mut a = match fill {
        Some(c) => format!(r#" fill="{}"{}"#, hex(c), alpha_attr("fill-opacity", c[3])),
        None => r#" fill="none""#.to_string(),
    };
    if let Some(st) = stroke {
        a.push_str(&stroke_attrs(st));
    }
    a
}

fn escape(t: &str) -> String {
    t.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::opacity;

    #[test]
    fn opacity_is_written_only_when_see_through() {
        assert_eq!(alpha_attr("x", 255), "");
        assert_eq!(alpha_attr("x", 0), r#" x="0.000""#);
        assert!((opacity([0, 0, 0, 51]) - 0.2).abs() < 1e-12);
    }
}
