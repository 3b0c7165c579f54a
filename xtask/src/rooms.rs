//! Synthetic top views of furnished rooms, drawn deterministically in code.
//!
//! Seed 000 plans on pictures taken by a ceiling Kinect camera; those pictures were not
//! published, so we draw rooms of the same size with furniture at plausible sizes
//! (6.34 mm per pixel: a 1.2 m table is about 190 px). Floors are light and textured,
//! furniture dark, so the paper's threshold (100) separates them; shadows and floor joints
//! are lighter than the threshold and must not become obstacles.

use std::path::Path;

use anyhow::Context;
use image::{Rgb, RgbImage};

/// A piece of furniture: a (possibly rotated) rectangle or a disc, with its colour.
#[derive(Clone, Copy)]
enum Shape {
    /// Centre (x, y) px, half sizes (hx, hy) px, rotation in degrees.
    Rect { cx: f64, cy: f64, hx: f64, hy: f64, deg: f64, rgb: [u8; 3] },
    /// Centre (x, y) px, radius px.
    Disc { cx: f64, cy: f64, r: f64, rgb: [u8; 3] },
}

impl Shape {
    fn contains(&self, x: f64, y: f64) -> bool {
        match *self {
            Shape::Rect { cx, cy, hx, hy, deg, .. } => {
                let (s, c) = deg.to_radians().sin_cos();
                let (dx, dy) = (x - cx, y - cy);
                let (u, v) = (c * dx + s * dy, -s * dx + c * dy);
                u.abs() <= hx && v.abs() <= hy
            }
            Shape::Disc { cx, cy, r, .. } => (x - cx).powi(2) + (y - cy).powi(2) <= r * r,
        }
    }

    fn rgb(&self) -> [u8; 3] {
        match *self {
            Shape::Rect { rgb, .. } | Shape::Disc { rgb, .. } => rgb,
        }
    }

    /// The same shape grown by `d` px (for the soft shadow under furniture).
    fn grown(&self, d: f64) -> Shape {
        match *self {
            Shape::Rect { cx, cy, hx, hy, deg, rgb } => {
                Shape::Rect { cx: cx + d, cy: cy + d, hx: hx + d, hy: hy + d, deg, rgb }
            }
            Shape::Disc { cx, cy, r, rgb } => Shape::Disc { cx: cx + d, cy: cy + d, r: r + d, rgb },
        }
    }
}

const WOOD: [u8; 3] = [92, 58, 30];
const SOFA: [u8; 3] = [40, 52, 90];
const SHELF: [u8; 3] = [60, 60, 60];
const PLANT: [u8; 3] = [30, 90, 40];
const CHAIR: [u8; 3] = [70, 40, 40];

/// The Table 2 room of seed 000: 960 x 640 px (6.34 mm/px, 6.09 x 4.06 m), cluttered, with
/// the start (74, 1953) mm and the goal (5501, 1308) mm (about (12, 308) px and
/// (868, 206) px, y down) left in the open.
fn room_960x640() -> Vec<Shape> {
    let r = |cx, cy, hx, hy, deg, rgb| Shape::Rect { cx, cy, hx, hy, deg, rgb };
    let d = |cx, cy, r, rgb| Shape::Disc { cx, cy, r, rgb };
    vec![
        // shelves along the top and bottom walls
        r(150.0, 22.0, 120.0, 20.0, 0.0, SHELF),
        r(520.0, 620.0, 160.0, 18.0, 0.0, SHELF),
        r(880.0, 600.0, 60.0, 38.0, 0.0, SHELF),
        // dining table with chairs
        r(250.0, 170.0, 95.0, 55.0, 0.0, WOOD),
        r(200.0, 95.0, 18.0, 16.0, 0.0, CHAIR),
        r(300.0, 95.0, 18.0, 16.0, 0.0, CHAIR),
        r(200.0, 245.0, 18.0, 16.0, 0.0, CHAIR),
        r(300.0, 245.0, 18.0, 16.0, 0.0, CHAIR),
        // sofa corner and a low table
        r(180.0, 470.0, 120.0, 40.0, 0.0, SOFA),
        r(80.0, 560.0, 40.0, 70.0, 0.0, SOFA),
        r(250.0, 380.0, 55.0, 30.0, 0.0, WOOD),
        // desk rotated, with an office chair
        r(470.0, 250.0, 100.0, 40.0, 25.0, WOOD),
        d(455.0, 330.0, 26.0, CHAIR),
        // round table in the middle-right
        d(640.0, 420.0, 70.0, WOOD),
        // cabinets and a plant near the goal side
        r(620.0, 110.0, 45.0, 90.0, 0.0, SHELF),
        r(760.0, 300.0, 35.0, 110.0, -15.0, SOFA),
        d(900.0, 80.0, 30.0, PLANT),
        d(820.0, 470.0, 24.0, PLANT),
        r(380.0, 520.0, 40.0, 30.0, 10.0, WOOD),
    ]
}

/// A small deterministic hash noise in [-1, 1] (floor texture), no RNG needed.
fn noise(x: u32, y: u32) -> f64 {
    let mut h = (x as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ (y as u64).wrapping_mul(0xC2B2_AE3D_27D4_EB4F);
    h ^= h >> 29;
    h = h.wrapping_mul(0xBF58_476D_1CE4_E5B9);
    h ^= h >> 32;
    (h % 2001) as f64 / 1000.0 - 1.0
}

/// Draws a room picture of `width x height` px with the given furniture.
fn draw(width: u32, height: u32, shapes: &[Shape]) -> RgbImage {
    let mut img = RgbImage::new(width, height);
    for (x, y, px) in img.enumerate_pixels_mut() {
        let (fx, fy) = (x as f64 + 0.5, y as f64 + 0.5);
        // Floor: light parquet with joints every 80 px and a little texture.
        let joint = x % 80 == 0 || y % 160 == 0;
        let base = if joint { 185.0 } else { 225.0 + 10.0 * noise(x, y) };
        let mut rgb = [base, base - 8.0, base - 20.0];
        // Soft shadows (still far above the threshold).
        if shapes.iter().any(|s| s.grown(6.0).contains(fx, fy)) {
            rgb = rgb.map(|c| c * 0.8);
        }
        if let Some(s) = shapes.iter().rev().find(|s| s.contains(fx, fy)) {
            let c = s.rgb();
            rgb = [0, 1, 2].map(|k| c[k] as f64 + 8.0 * noise(x + 7, y + 13));
        }
        *px = Rgb(rgb.map(|c| c.clamp(0.0, 255.0) as u8));
    }
    img
}

/// Writes the room pictures used by the scenarios and the peer comparisons into `dir`:
/// `room_960x640.png` (RGB) and `room_960x640.pgm` (grey, for the OMPL peer).
pub fn write_rooms(dir: &Path) -> anyhow::Result<Vec<std::path::PathBuf>> {
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    let img = draw(960, 640, &room_960x640());
    let png = dir.join("room_960x640.png");
    img.save(&png).with_context(|| format!("writing {}", png.display()))?;
    let grey = image::DynamicImage::ImageRgb8(img).to_luma8();
    let pgm = dir.join("room_960x640.pgm");
    grey.save(&pgm).with_context(|| format!("writing {}", pgm.display()))?;
    Ok(vec![png, pgm])
}
