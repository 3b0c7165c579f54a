//! `hyplan map`: turn a picture, ROS map or MovingAI map into a three-zone safe map.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::Context as _;
use envmap::{CellRect, InputFrame, LoadOptions, LoadedMap, MapKind};
use hyplan_core::Point2;

/// Options of `hyplan map`.
#[derive(clap::Args)]
pub struct Args {
    /// An image (PNG, PGM, PPM), a ROS map_server `.yaml`, a MovingAI `.map` or a ROS 2
    /// bag (`.mcap`: its last `nav_msgs/msg/OccupancyGrid` on `--topic`).
    pub input: PathBuf,
    /// ROS 2 bags: the topic of the map.
    #[arg(long, default_value = envmap::DEFAULT_MAP_TOPIC)]
    pub topic: String,
    /// Pictures: pixels with luminance below this are obstacles (seed 000: 100).
    #[arg(long, default_value_t = 100)]
    pub threshold: u8,
    /// Pictures: pixels with luminance at or above the threshold are obstacles instead.
    #[arg(long)]
    pub invert: bool,
    /// Replace each obstacle by its bounding rectangle before adding the high-risk band.
    #[arg(long)]
    pub rectangles: bool,
    /// Radius of the high-risk band: cells for pictures and `.map`, metres for ROS maps
    /// [default: 20 for pictures, 0 for `.map` and ROS maps].
    #[arg(long, value_name = "R", allow_hyphen_values = true)]
    pub safety_radius: Option<f64>,
    /// ROS maps: unknown cells are free (default: forbidden).
    #[arg(long)]
    pub unknown_free: bool,
    /// Write the zones as a picture, format by extension: PNG (white safe, grey high-risk,
    /// black forbidden, blue rectangles), binary PGM (`.pgm`, `P5`: the same colours as
    /// grey levels 255, 160, 0 and 85, which Nav2's trinary rule reads as free, unknown,
    /// occupied and occupied) or PPM (`.ppm`, `P6`).
    #[arg(long, value_name = "PICTURE")]
    pub out: Option<PathBuf>,
    /// Write the map as a ROS map: this YAML (`mode: scale`) plus a binary PGM with the
    /// same stem: safe 254, high-risk 128 (between the thresholds: a graded cost in scale
    /// mode, unknown in trinary mode), forbidden 0.
    #[arg(long, value_name = "YAML")]
    pub yaml: Option<PathBuf>,
    /// Print one JSON object instead of a summary.
    #[arg(long)]
    pub json: bool,
    /// Memory limit: maps with more cells (width x height) are refused before loading.
    #[arg(long, value_name = "N", default_value_t = envmap::DEFAULT_MAX_CELLS)]
    pub max_cells: usize,
}

/// Runs `hyplan map`.
pub fn run(args: &Args) -> anyhow::Result<ExitCode> {
    let opts = LoadOptions {
        threshold: args.threshold,
        invert: args.invert,
        rectangles: args.rectangles,
        safety_radius: args.safety_radius,
        unknown_free: args.unknown_free,
        max_cells: args.max_cells,
    };
    let loaded = super::load_map_topic(&args.input, &args.topic, &opts)?;
    let rects: Vec<CellRect> = loaded.components.iter().map(|c| c.rect).collect();
    if let Some(out) = &args.out {
        let shown: &[CellRect] = if args.rectangles { &rects } else { &[] };
        envmap::write_picture(&envmap::render_zones(&loaded.map, shown), out).with_context(
            || {
                format!(
                    "writing --out {} (a picture, by its extension: .png, .pgm or .ppm)",
                    out.display()
                )
            },
        )?;
    }
    if let Some(yaml) = &args.yaml {
        // The input's yaw again: the grid is the input's, turned as it was.
        envmap::write_ros_turned(&loaded.map, loaded.frame.yaw(), yaml)
            .with_context(|| format!("writing --yaml {}", yaml.display()))?;
    }
    if args.json {
        outln!(
            "{}",
            serde_json::to_string(&summary_json(args, &loaded, &rects))?
        )?;
    } else {
        print_summary(args, &loaded)?;
    }
    Ok(ExitCode::SUCCESS)
}

fn kind_name(kind: MapKind) -> &'static str {
    match kind {
        MapKind::MovingAi => "movingai",
        MapKind::Ros => "ros",
        MapKind::Picture => "picture",
        MapKind::Mcap => "mcap",
    }
}

/// The rectangle's box in the input frame: `([x_min, y_min], [x_max, y_max])`.
fn rect_in_input(loaded: &LoadedMap, r: &CellRect) -> ([f64; 2], [f64; 2]) {
    let b = r.to_world(&loaded.map);
    let (ax, ay) = loaded.frame.from_world(b.min);
    let (bx, by) = loaded.frame.from_world(b.max);
    ([ax.min(bx), ay.min(by)], [ax.max(bx), ay.max(by)])
}

fn summary_json(args: &Args, loaded: &LoadedMap, rects: &[CellRect]) -> serde_json::Value {
    let map = &loaded.map;
    let [free, risk, forbidden] = map.zone_counts();
    let obstacles: Vec<serde_json::Value> = loaded
        .components
        .iter()
        .zip(rects)
        .map(|(c, r)| {
            let (min, max) = rect_in_input(loaded, r);
            let cells = if args.rectangles {
                r.width() * r.height()
            } else {
                c.cells
            };
            serde_json::json!({ "cells": cells, "min": min, "max": max })
        })
        .collect();
    let frame = match loaded.frame {
        InputFrame::Cells { .. } => "cells_y_down",
        InputFrame::World => "world_y_up",
        InputFrame::MapFrame { .. } => "map_frame_rotated",
    };
    serde_json::json!({
        "input": args.input.display().to_string(),
        "kind": kind_name(loaded.kind),
        "width": map.width(),
        "height": map.height(),
        "resolution": map.resolution(),
        "origin": [map.origin().x, map.origin().y],
        "frame": frame,
        "free": free,
        "risk": risk,
        "forbidden": forbidden,
        "obstacle_shape": if args.rectangles { "rectangles" } else { "components" },
        "obstacles": obstacles,
    })
}

fn print_summary(args: &Args, loaded: &LoadedMap) -> std::io::Result<()> {
    let map = &loaded.map;
    let [free, risk, forbidden] = map.zone_counts();
    let o: Point2 = map.origin();
    let kind = match loaded.kind {
        MapKind::MovingAi => "MovingAI map",
        MapKind::Ros => "ROS map",
        MapKind::Picture => "picture",
        MapKind::Mcap => "ROS 2 bag map",
    };
    outln!(
        "{}: {kind}, {} x {} cells, resolution {}, origin ({}, {})",
        args.input.display(),
        map.width(),
        map.height(),
        map.resolution(),
        o.x,
        o.y
    )?;
    outln!("zones: {free} safe, {risk} high-risk, {forbidden} forbidden")?;
    let shape = if args.rectangles {
        "bounding rectangles"
    } else {
        "8-connected components"
    };
    outln!("obstacles: {} ({shape})", loaded.components.len())?;
    outln!("coordinates: {}", loaded.frame.describe())?;
    for (flag, path) in [("zones", &args.out), ("ROS map", &args.yaml)] {
        if let Some(p) = path {
            outln!("wrote {flag}: {}", show(p))?;
        }
    }
    Ok(())
}

fn show(p: &Path) -> String {
    p.display().to_string()
}
