//! Draws the figures of `docs/postproc.md`: one path before and after each smoothing
//! method, and the speed and turn-rate profiles.
//!
//! Run from the workspace root: `cargo run -p postproc --example figures`. It writes
//! `docs/figures/postproc_*.svg` (hand-written SVG, no plotting dependency) and prints the
//! numbers quoted in the doc.

use std::fmt::Write as _;
use std::path::Path;

use envmap::GridMap;
use hyplan_core::{Point2, Workspace, Zone};
use postproc::{Limits, PathMetrics, Repair, Smoothed, Smoothing, Timing, smooth_checked};

/// Grid size in cells (world units = cells, origin lower left, y up).
const W: usize = 20;
const H: usize = 14;
/// Pixels per cell.
const PX: f64 = 36.0;

/// Blocked rectangles `(x0, y0, x1, y1)` in cells, half-open.
const BLOCKS: [(usize, usize, usize, usize); 3] = [(5, 0, 8, 8), (11, 6, 14, 14), (16, 2, 18, 5)];

/// The world: a `W x H` map of unit cells with the blocks forbidden. Its exact segment
/// check (closed segments against closed cells) is the smoothing oracle.
fn world() -> GridMap {
    let mut map = GridMap::filled(W, H, Zone::Free).expect("a valid size");
    for &(x0, y0, x1, y1) in &BLOCKS {
        for j in y0..y1 {
            for i in x0..x1 {
                map.set_cell_zone(i, j, Zone::Forbidden);
            }
        }
    }
    map
}

/// An RRT-like zigzag from (1.5, 1.5) to (18.5, 12.5).
fn input_path() -> Vec<Point2> {
    [
        (1.5, 1.5),
        (2.8, 3.9),
        (1.9, 6.2),
        (3.6, 8.7),
        (4.6, 10.1),
        (6.8, 9.3),
        (9.2, 10.2),
        (9.6, 7.4),
        (10.3, 4.8),
        (12.4, 4.2),
        (14.9, 3.1),
        (15.2, 5.6),
        (17.3, 6.4),
        (16.4, 9.1),
        (18.5, 12.5),
    ]
    .iter()
    .map(|&(x, y)| Point2::new(x, y))
    .collect()
}

fn sx(x: f64) -> f64 {
    x * PX + 10.0
}

fn sy(y: f64) -> f64 {
    (H as f64 - y) * PX + 40.0
}

fn polyline(svg: &mut String, pts: &[Point2], style: &str) {
    let coords: Vec<String> = pts
        .iter()
        .map(|p| format!("{:.2},{:.2}", sx(p.x), sy(p.y)))
        .collect();
    let _ = writeln!(
        svg,
        r#"<polyline points="{}" fill="none" {style}/>"#,
        coords.join(" ")
    );
}

fn dots(svg: &mut String, pts: &[Point2], r: f64, fill: &str) {
    for p in pts {
        let _ = writeln!(
            svg,
            r#"<circle cx="{:.2}" cy="{:.2}" r="{r}" fill="{fill}"/>"#,
            sx(p.x),
            sy(p.y)
        );
    }
}

fn scene(map: &GridMap, title: &str, input: &[Point2], s: &Smoothed) -> String {
    let (w, h) = (W as f64 * PX + 20.0, H as f64 * PX + 50.0);
    let mut svg = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif">
<rect width="{w}" height="{h}" fill="white"/>
<text x="10" y="24" font-size="15">{title}</text>
"#
    );
    for j in 0..H {
        for i in 0..W {
            // The workspace's one zone scheme (envmap::zone_colour).
            let [r, g, b] = envmap::zone_colour(map.cell_zone(i, j));
            let fill = format!("#{r:02x}{g:02x}{b:02x}");
            let _ = writeln!(
                svg,
                r##"<rect x="{:.1}" y="{:.1}" width="{PX}" height="{PX}" fill="{fill}" stroke="#ddd" stroke-width="0.5"/>"##,
                sx(i as f64),
                sy(j as f64 + 1.0)
            );
        }
    }
    polyline(
        &mut svg,
        input,
        r##"stroke="#888" stroke-width="1.5" stroke-dasharray="5,4""##,
    );
    dots(&mut svg, input, 3.0, "#888");
    if s.method == Smoothing::BSpline {
        polyline(&mut svg, &s.nodes, r##"stroke="#7aa6e0" stroke-width="1""##);
    }
    polyline(
        &mut svg,
        &s.points,
        r##"stroke="#d62728" stroke-width="2.5""##,
    );
    let mut defining = s.nodes.clone();
    defining.dedup();
    dots(&mut svg, &defining, 4.5, "#1f5fbf");
    for r in &s.repairs {
        let at = match *r {
            Repair::InsertedNode { at } => at,
            Repair::Straightened { from, to } => nalgebra::center(&from, &to),
            Repair::RaisedMultiplicity { node, .. } => node,
            _ => continue,
        };
        let _ = writeln!(
            svg,
            r##"<circle cx="{:.2}" cy="{:.2}" r="9" fill="none" stroke="#ff9900" stroke-width="2.5"/>"##,
            sx(at.x),
            sy(at.y)
        );
    }
    svg.push_str("</svg>\n");
    svg
}

/// v(t) (top) and omega(t) (bottom) of several timings on shared axes.
fn profiles(timings: &[(&str, &str, Timing)], limits: &Limits) -> String {
    let (w, h) = (760.0, 460.0);
    let (left, right) = (60.0, 740.0);
    let t_max = timings
        .iter()
        .fold(0.0_f64, |m, (_, _, t)| m.max(t.transfer_time));
    let x = |t: f64| left + (right - left) * t / t_max;
    let mut svg = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif" font-size="12">
<rect width="{w}" height="{h}" fill="white"/>
"#
    );
    // Two panels: (top, bottom, label, value range, value of a point).
    type Value = fn(&postproc::ProfilePoint) -> f64;
    let panels: [(f64, f64, &str, f64, f64, Value); 2] = [
        (30.0, 200.0, "v (cells/s)", 0.0, limits.v_max * 1.1, |p| p.v),
        (
            250.0,
            420.0,
            "omega (rad/s)",
            -limits.omega_max * 1.1,
            limits.omega_max * 1.1,
            |p| p.omega,
        ),
    ];
    for (top, bottom, label, lo, hi, value) in panels {
        let y = |v: f64| bottom - (bottom - top) * (v - lo) / (hi - lo);
        let _ = writeln!(
            svg,
            r##"<rect x="{left}" y="{top}" width="{}" height="{}" fill="none" stroke="#999"/>
<text x="{}" y="{}">{label}</text>"##,
            right - left,
            bottom - top,
            left + 4.0,
            top + 14.0
        );
        let ticks = if lo < 0.0 {
            vec![lo / 1.1, 0.0, hi / 1.1]
        } else {
            vec![0.0, hi / 1.1]
        };
        for v in ticks {
            let _ = writeln!(
                svg,
                r##"<line x1="{left}" x2="{right}" y1="{:.1}" y2="{:.1}" stroke="#eee"/><text x="8" y="{:.1}">{v:.2}</text>"##,
                y(v),
                y(v),
                y(v) + 4.0
            );
        }
        for (name, colour, t) in timings {
            let pts: Vec<String> = t
                .profile
                .iter()
                .map(|p| format!("{:.2},{:.2}", x(p.t), y(value(p))))
                .collect();
            let _ = writeln!(
                svg,
                r#"<polyline points="{}" fill="none" stroke="{colour}" stroke-width="1.5"><title>{name}</title></polyline>"#,
                pts.join(" ")
            );
        }
    }
    for (k, (name, colour, t)) in timings.iter().enumerate() {
        let _ = writeln!(
            svg,
            r#"<text x="{}" y="446" fill="{colour}">{name}: {:.1} s</text>"#,
            left + 200.0 * k as f64,
            t.transfer_time
        );
    }
    let _ = writeln!(
        svg,
        r#"<text x="{}" y="446">t from 0 to {t_max:.1} s</text>"#,
        right - 140.0
    );
    svg.push_str("</svg>\n");
    svg
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/figures");
    std::fs::create_dir_all(&out)?;
    let map = world();
    let segment_free = |a, b| map.segment_free(a, b);
    let input = input_path();
    assert!(
        input.windows(2).all(|w| segment_free(w[0], w[1])),
        "the input path must be free"
    );
    let limits = Limits::new(1.0, 1.0, 0.5)?;
    let m = PathMetrics::of(&input);
    println!(
        "input: length {:.2}, {} nodes, {} turns, polyline time {:.1} s",
        m.length,
        m.nodes,
        m.turns,
        postproc::time_polyline(&input, &limits)?.transfer_time
    );
    let mut timings = Vec::new();
    for method in Smoothing::ALL {
        let s = smooth_checked(&input, method, 0.25, segment_free)?;
        let t = s.time(&limits)?;
        let m = s.metrics();
        let mut nodes = s.nodes.clone();
        nodes.dedup();
        println!(
            "{method}: length {:.2}, {} nodes, {} turns, max curvature {:.2}, {} samples, {} repairs {:?}, transfer {:.1} s",
            m.length,
            nodes.len(),
            m.turns,
            m.max_curvature,
            s.points.len(),
            s.repairs.len(),
            s.repairs,
            t.transfer_time
        );
        let title = format!(
            "{method}: length {:.1} (input {:.1}), {} nodes, {} repairs, transfer {:.1} s",
            m.length,
            hyplan_core::path_length(&input),
            nodes.len(),
            s.repairs.len(),
            t.transfer_time
        );
        std::fs::write(
            out.join(format!("postproc_{}.svg", method.name().replace('-', "_"))),
            scene(&map, &title, &input, &s),
        )?;
        match method {
            Smoothing::Prune => timings.push(("prune (stop and turn)", "#1f77b4", t)),
            Smoothing::Pchip => timings.push(("pchip", "#d62728", t)),
            Smoothing::BSpline => timings.push(("bspline", "#2ca02c", t)),
            _ => {}
        }
    }
    std::fs::write(out.join("postproc_timing.svg"), profiles(&timings, &limits))?;
    Ok(())
}
