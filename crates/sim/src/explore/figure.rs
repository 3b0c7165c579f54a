//! Figures of an exploration: the built map at a snapshot with the robot's track so far,
//! the trees (global green, local blue), the published points (orange), the filtered
//! frontiers (magenta) and the goal (red ring), over the true world's outlines.

use std::fmt::Write as _;

use crate::explore::run::{ExploreOutcome, Snapshot};
use crate::record::{polyline, world_svg_with};
use crate::world::World;

/// The SVG of one snapshot of `outcome`.
#[must_use]
pub fn snapshot_svg(outcome: &ExploreOutcome, snap: &Snapshot, world: &World) -> String {
    let mut s = String::new();
    world_svg_with(Some(&snap.map), world, &mut s);
    let mut edges = |list: &[(hyplan_core::Point2, hyplan_core::Point2)], colour: &str| {
        let _ = write!(
            s,
            r#"<path fill="none" stroke="{colour}" stroke-width="0.02" d=""#
        );
        for (a, b) in list {
            let _ = write!(s, "M{:.3} {:.3}L{:.3} {:.3}", a.x, a.y, b.x, b.y);
        }
        s.push_str("\"/>\n");
    };
    edges(&snap.global_edges, "#2a2");
    edges(&snap.local_edges, "#36c");
    let track = polyline(
        outcome
            .track
            .iter()
            .take_while(|(t, _)| *t <= snap.t)
            .map(|(_, p)| (p.x, p.y)),
    );
    let _ = writeln!(
        s,
        r##"<polyline points="{track}" fill="none" stroke="#000" stroke-width="0.06"/>"##
    );
    for p in &snap.published {
        let _ = writeln!(
            s,
            r##"<circle cx="{:.3}" cy="{:.3}" r="0.05" fill="#f80"/>"##,
            p.x, p.y
        );
    }
    for p in &snap.frontiers {
        let _ = writeln!(
            s,
            r##"<circle cx="{:.3}" cy="{:.3}" r="0.15" fill="#d0d"/>"##,
            p.x, p.y
        );
    }
    if let Some(g) = snap.goal {
        let _ = writeln!(
            s,
            r##"<circle cx="{:.3}" cy="{:.3}" r="0.3" fill="none" stroke="#e00" stroke-width="0.06"/>"##,
            g.x, g.y
        );
    }
    let _ = writeln!(
        s,
        r##"<circle cx="{:.3}" cy="{:.3}" r="0.18" fill="#fc0" stroke="#000" stroke-width="0.03"/>"##,
        snap.pose.x, snap.pose.y
    );
    s.push_str("</g></svg>\n");
    s
}

/// The frames of `outcome` (see [`crate::explore::Exploration::frame_period`]) as an
/// animated PNG (APNG; browsers play it): one pixel per map cell, free white, occupied
/// black, unknown grey, the robot's track so far dark blue and the robot red; `delay_ms`
/// per frame.
///
/// # Errors
///
/// No frames, or the PNG encoder's error, as text.
pub fn animation_png(outcome: &ExploreOutcome, delay_ms: u16) -> Result<Vec<u8>, String> {
    let (w, h) = (outcome.map.width(), outcome.map.height());
    if outcome.frames.is_empty() {
        return Err("no frames were kept (exploration.frame_period is None)".into());
    }
    let n = u32::try_from(outcome.frames.len()).map_err(|e| e.to_string())?;
    let mut bytes = Vec::new();
    {
        // Five colours: an indexed image is a third of RGB's bytes to compress, and the
        // fast deflate keeps a 100-frame animation from costing more than the run.
        const WHITE: u8 = 0;
        const BLACK: u8 = 1;
        const GREY: u8 = 2;
        const TRACK: u8 = 3;
        const ROBOT: u8 = 4;
        let mut enc = png::Encoder::new(&mut bytes, w as u32, h as u32);
        enc.set_color(png::ColorType::Indexed);
        enc.set_depth(png::BitDepth::Eight);
        enc.set_palette(vec![
            255, 255, 255, 0, 0, 0, 160, 160, 160, 30, 60, 200, 220, 0, 0,
        ]);
        enc.set_compression(png::Compression::Fast);
        enc.set_animated(n, 0).map_err(|e| e.to_string())?;
        enc.set_frame_delay(delay_ms, 1000)
            .map_err(|e| e.to_string())?;
        let mut writer = enc.write_header().map_err(|e| e.to_string())?;
        let res = outcome.map.params.resolution;
        let o = outcome.map.origin();
        let cell = |x: f64, y: f64| {
            let (i, j) = (((x - o.x) / res).floor(), ((y - o.y) / res).floor());
            (i >= 0.0 && j >= 0.0 && (i as usize) < w && (j as usize) < h)
                .then_some((i as usize, j as usize))
        };
        let mut pixels = vec![0u8; w * h];
        for (t, pose, values) in &outcome.frames {
            for j in 0..h {
                // PNG rows go top-down; the map's rows bottom-up.
                let row = h - 1 - j;
                for (px, &v) in pixels[row * w..(row + 1) * w]
                    .iter_mut()
                    .zip(&values[j * w..(j + 1) * w])
                {
                    *px = match v {
                        crate::mapping::FREE => WHITE,
                        crate::mapping::OCCUPIED => BLACK,
                        _ => GREY,
                    };
                }
            }
            let mut put = |x: f64, y: f64, c: u8| {
                if let Some((i, j)) = cell(x, y) {
                    pixels[(h - 1 - j) * w + i] = c;
                }
            };
            for (_, p) in outcome.track.iter().take_while(|(s, _)| s <= t) {
                put(p.x, p.y, TRACK);
            }
            for dx in -2i32..=2 {
                for dy in -2i32..=2 {
                    put(
                        pose.x + f64::from(dx) * res,
                        pose.y + f64::from(dy) * res,
                        ROBOT,
                    );
                }
            }
            writer
                .write_image_data(&pixels)
                .map_err(|e| e.to_string())?;
        }
        writer.finish().map_err(|e| e.to_string())?;
    }
    Ok(bytes)
}
