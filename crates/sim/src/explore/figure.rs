//! Figures of an exploration: the built map at a snapshot with the robot's track so far,
//! the trees (global green, local blue), the published points (orange), the filtered
//! frontiers (magenta) and the goal (red ring), over the true world's outlines; and the
//! run as an animated PNG. `viz` draws them; this module says what they show.

use hyplan_core::Point2;
use viz::{FigureError, GridImage, Mark, Scene, Stroke, rgb};

use crate::explore::run::{ExploreOutcome, Snapshot};
use crate::mapping::{FREE, OCCUPIED};
use crate::record::world_scene;
use crate::world::World;

/// Pixels per metre of the snapshot figures (as the run's figures, `crate::record`).
const SCALE: f64 = 30.0;

/// The SVG of one snapshot of `outcome`.
///
/// # Errors
///
/// [`FigureError`] when the map layer cannot be encoded.
pub fn snapshot_svg(
    outcome: &ExploreOutcome,
    snap: &Snapshot,
    world: &World,
) -> Result<String, FigureError> {
    snapshot_scene(outcome, snap, world).to_svg()
}

/// The scene of [`snapshot_svg`] (also drawn as PNG by [`Scene::png_bytes`]).
#[must_use]
pub fn snapshot_scene(outcome: &ExploreOutcome, snap: &Snapshot, world: &World) -> Scene {
    let mut scene = world_scene(Some(&snap.map), world);
    for (edges, colour) in [
        (&snap.global_edges, rgb(0x2, 0xa, 0x2)),
        (&snap.local_edges, rgb(0x3, 0x6, 0xc)),
    ] {
        scene.push(Mark::Segments {
            pairs: edges.clone(),
            stroke: Stroke::new(colour, 0.02 * SCALE),
        });
    }
    let track: Vec<Point2> = outcome
        .track
        .iter()
        .take_while(|(t, _)| *t <= snap.t)
        .map(|(_, p)| Point2::new(p.x, p.y))
        .collect();
    scene.push(Mark::polyline(
        track,
        Stroke::new([0, 0, 0, 255], 0.06 * SCALE),
    ));
    for &p in &snap.published {
        scene.push(Mark::disc(p, 0.05, rgb(0xf, 0x8, 0x0)));
    }
    for &p in &snap.frontiers {
        scene.push(Mark::disc(p, 0.15, rgb(0xd, 0x0, 0xd)));
    }
    if let Some(g) = snap.goal {
        scene.push(Mark::ring(
            g,
            0.3,
            Stroke::new(rgb(0xe, 0x0, 0x0), 0.06 * SCALE),
        ));
    }
    scene.push(Mark::Disc {
        center: Point2::new(snap.pose.x, snap.pose.y),
        radius: 0.18,
        fill: Some(rgb(0xf, 0xc, 0x0)),
        stroke: Some(Stroke::new([0, 0, 0, 255], 0.03 * SCALE)),
    });
    scene
}

/// The frames of `outcome` (see [`crate::explore::Exploration::frame_period`]) as an
/// animated PNG (APNG; browsers play it): one pixel per map cell, free white, occupied
/// black, unknown grey, the robot's track so far dark blue and the robot red; `delay_ms`
/// per frame.
///
/// # Errors
///
/// [`FigureError::NoFrames`] when no frame was kept (`exploration.frame_period` is
/// `None`), or the encoder's error.
pub fn animation_png(outcome: &ExploreOutcome, delay_ms: u16) -> Result<Vec<u8>, FigureError> {
    const WHITE: u8 = 0;
    const BLACK: u8 = 1;
    const GREY: u8 = 2;
    const TRACK: u8 = 3;
    const ROBOT: u8 = 4;
    let palette = vec![
        [255, 255, 255, 255],
        [0, 0, 0, 255],
        [160, 160, 160, 255],
        [30, 60, 200, 255],
        [220, 0, 0, 255],
    ];
    let map = &outcome.map;
    let res = map.params.resolution;
    let empty = GridImage::filled(map.frame(), palette);
    let frames = outcome.frames.replay().map(|(t, pose, values)| {
        let mut grid = empty.clone();
        for (cell, &v) in grid.cells_mut().iter_mut().zip(&values) {
            *cell = match v {
                FREE => WHITE,
                OCCUPIED => BLACK,
                _ => GREY,
            };
        }
        for (_, p) in outcome.track.iter().take_while(|(s, _)| *s <= t) {
            grid.paint(Point2::new(p.x, p.y), TRACK);
        }
        for dx in -2i32..=2 {
            for dy in -2i32..=2 {
                let at = Point2::new(pose.x + f64::from(dx) * res, pose.y + f64::from(dy) * res);
                grid.paint(at, ROBOT);
            }
        }
        grid
    });
    viz::apng_indexed(frames, delay_ms)
}
