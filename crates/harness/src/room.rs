//! Top views of furnished rooms, drawn in code from a list of furniture.
//!
//! Seed 000 plans on pictures taken by ceiling Kinect cameras; those pictures were not
//! published, so scenarios describe rooms by their furniture (rectangles, possibly rotated,
//! and discs, in pixels) and the picture is drawn here, deterministically, then run
//! through the real `envmap` pipeline. Floors are light and textured with joints, shadows
//! darken the floor around furniture (still far above the paper's threshold of 100) and
//! furniture is dark, so binarization has real work to do.

use envmap::Picture;
use serde::{Deserialize, Serialize};

/// A piece of furniture in a room picture, pixels, y down from the top row.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Furniture {
    /// A rectangle centred at `(cx, cy)` with half sizes `hx`, `hy`, rotated by `deg`
    /// degrees, in colour `rgb`.
    Rect {
        /// Centre x, px.
        cx: f64,
        /// Centre y, px (down).
        cy: f64,
        /// Half width, px.
        hx: f64,
        /// Half height, px.
        hy: f64,
        /// Rotation, degrees.
        #[serde(default)]
        deg: f64,
        /// Colour.
        rgb: [u8; 3],
    },
    /// A disc centred at `(cx, cy)` with radius `r`, in colour `rgb`.
    Disc {
        /// Centre x, px.
        cx: f64,
        /// Centre y, px (down).
        cy: f64,
        /// Radius, px.
        r: f64,
        /// Colour.
        rgb: [u8; 3],
    },
}

impl Furniture {
    /// Whether the pixel centre `(x, y)` lies on the piece.
    #[must_use]
    pub fn contains(&self, x: f64, y: f64) -> bool {
        match *self {
            Self::Rect {
                cx,
                cy,
                hx,
                hy,
                deg,
                ..
            } => {
                let (s, c) = deg.to_radians().sin_cos();
                let (dx, dy) = (x - cx, y - cy);
                let (u, v) = (c * dx + s * dy, -s * dx + c * dy);
                u.abs() <= hx && v.abs() <= hy
            }
            Self::Disc { cx, cy, r, .. } => (x - cx).powi(2) + (y - cy).powi(2) <= r * r,
        }
    }

    /// The piece's colour.
    #[must_use]
    pub const fn rgb(&self) -> [u8; 3] {
        match *self {
            Self::Rect { rgb, .. } | Self::Disc { rgb, .. } => rgb,
        }
    }

    /// The same piece grown by `d` px and moved by `(d, d)`: its shadow.
    #[must_use]
    pub fn shadow(&self, d: f64) -> Self {
        match *self {
            Self::Rect {
                cx,
                cy,
                hx,
                hy,
                deg,
                rgb,
            } => Self::Rect {
                cx: cx + d,
                cy: cy + d,
                hx: hx + d,
                hy: hy + d,
                deg,
                rgb,
            },
            Self::Disc { cx, cy, r, rgb } => Self::Disc {
                cx: cx + d,
                cy: cy + d,
                r: r + d,
                rgb,
            },
        }
    }

    /// Half the diagonal of the piece's bounding box (rectangles) or its radius, px.
    #[must_use]
    pub fn reach(&self) -> f64 {
        match *self {
            Self::Rect { hx, hy, .. } => hx.hypot(hy),
            Self::Disc { r, .. } => r,
        }
    }

    /// Centre, px.
    #[must_use]
    pub const fn center(&self) -> (f64, f64) {
        match *self {
            Self::Rect { cx, cy, .. } | Self::Disc { cx, cy, .. } => (cx, cy),
        }
    }
}

/// A small deterministic hash noise in [-1, 1] per 2 x 2 block (floor texture).
fn noise(x: usize, y: usize) -> f64 {
    let mut h = ((x / 2) as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15)
        ^ ((y / 2) as u64).wrapping_mul(0xC2B2_AE3D_27D4_EB4F);
    h ^= h >> 29;
    h = h.wrapping_mul(0xBF58_476D_1CE4_E5B9);
    h ^= h >> 32;
    (h % 9) as f64 / 4.0 - 1.0
}

/// Draws a room picture of `width x height` px with the given furniture (later pieces on
/// top of earlier ones).
///
/// ```
/// use harness::{Furniture, draw_room};
/// let room = draw_room(64, 48, &[Furniture::Disc { cx: 32.0, cy: 24.0, r: 10.0, rgb: [90, 60, 30] }]);
/// assert!(room.luminance(32, 24) < 100); // furniture is darker than the paper's threshold
/// assert!(room.luminance(2, 2) > 150); // the floor is light
/// ```
#[must_use]
pub fn draw_room(width: usize, height: usize, furniture: &[Furniture]) -> Picture {
    let mut data = Vec::with_capacity(width * height * 3);
    for y in 0..height {
        for x in 0..width {
            let (fx, fy) = (x as f64 + 0.5, y as f64 + 0.5);
            // Floor: light parquet with joints every 80 x 160 px and a little texture.
            let joint = x % 80 == 0 || y % 160 == 0;
            let base = if joint {
                185.0
            } else {
                225.0 + 6.0 * noise(x, y)
            };
            let mut rgb = [base, base - 8.0, base - 20.0];
            if furniture.iter().any(|s| s.shadow(6.0).contains(fx, fy)) {
                rgb = rgb.map(|c| c * 0.8);
            }
            if let Some(s) = furniture.iter().rev().find(|s| s.contains(fx, fy)) {
                let c = s.rgb();
                rgb = [0, 1, 2].map(|k| f64::from(c[k]) + 6.0 * noise(x + 7, y + 13));
            }
            data.extend(rgb.map(|c| c.clamp(0.0, 255.0) as u8));
        }
    }
    // The buffer has exactly width * height * 3 bytes by construction.
    Picture::rgb(width, height, data)
        .unwrap_or_else(|| Picture::filled_rgb(width, height, [255; 3]))
}
