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
