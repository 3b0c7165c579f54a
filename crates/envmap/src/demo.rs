//! A synthetic top-view room, for examples, tests and benchmarks.

use crate::Picture;

/// A synthetic top-view picture of a furnished room, `width x height` pixels, RGB: a light
/// floor, a partition wall, a table with four chairs, a round table, an
/// L-shaped kitchen counter, a sofa, a bed, shelves, plant pots, and a light rug that is
/// **not** an obstacle at the default threshold (luminance about 147 > 100).
///
/// Every piece of furniture is darker than luminance 100, so the default
/// [`Pipeline`](crate::Pipeline) finds them all. The layout is given in fractions of the
/// picture size, so any size draws the same room (sizes below about 40 x 30 pixels lose
/// the small pieces).
///
/// ```
/// use envmap::{demo_room, Pipeline};
/// let room = demo_room(320, 240);
/// let out = Pipeline::default().run(&room)?;
/// assert!(out.components.len() >= 10);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[must_use]
pub fn demo_room(width: usize, height: usize) -> Picture {
    const FLOOR: [u8; 3] = [226, 214, 190];
    const WALL: [u8; 3] = [40, 40, 48];
    const WOOD: [u8; 3] = [96, 62, 38];
    const CHAIR: [u8; 3] = [70, 50, 40];
    const SOFA: [u8; 3] = [40, 60, 110];
    const BED: [u8; 3] = [110, 40, 50];
    const COUNTER: [u8; 3] = [60, 66, 70];
    const PLANT: [u8; 3] = [30, 100, 40];
    const RUG: [u8; 3] = [190, 140, 120];
    let mut pic = Picture::filled_rgb(width, height, FLOOR);
    let (w, h) = (width as f64, height as f64);
    // Fractional rectangle [x0, x1) x [y0, y1), y down.
    let mut rect = |x0: f64, y0: f64, x1: f64, y1: f64, c: [u8; 3]| {
        let (px0, px1) = ((x0 * w) as usize, (x1 * w) as usize);
        let (py0, py1) = ((y0 * h) as usize, (y1 * h) as usize);
        for y in py0..py1.min(height) {
            for x in px0..px1.min(width) {
                pic.set_rgb(x, y, c);
            }
        }
    };
    // Rug first: furniture is drawn over it.
    rect(0.12, 0.55, 0.42, 0.88, RUG);
    // A short partition wall (no enclosing walls: the picture's border is the room's,
    // as in seed 000's arena; an enclosing wall would be one component whose bounding
    // rectangle covers the whole map).
    rect(0.45, 0.0, 0.47, 0.22, WALL);
    // Dining table and four chairs.
    rect(0.16, 0.18, 0.34, 0.32, WOOD);
    for (cx, cy) in [(0.19, 0.12), (0.28, 0.12), (0.19, 0.34), (0.28, 0.34)] {
        rect(cx, cy, cx + 0.04, cy + 0.04, CHAIR);
    }
    // Sofa facing the rug, and a coffee table on the rug.
    rect(0.14, 0.80, 0.40, 0.86, SOFA);
    rect(0.22, 0.64, 0.32, 0.71, WOOD);
    // L-shaped kitchen counter in the top-right corner.
    rect(0.62, 0.04, 0.96, 0.10, COUNTER);
    rect(0.90, 0.04, 0.96, 0.36, COUNTER);
    // Bed and shelves.
    rect(0.62, 0.56, 0.80, 0.90, BED);
    rect(0.86, 0.50, 0.96, 0.56, WOOD);
    rect(0.86, 0.62, 0.96, 0.68, WOOD);
    // Round table and plant pots (discs).
    let mut disc = |cx: f64, cy: f64, r: f64, c: [u8; 3]| {
        let (cx, cy, r) = (cx * w, cy * h, r * w.min(h));
        let (y0, y1) = ((cy - r).max(0.0) as usize, (cy + r).ceil() as usize);
        let (x0, x1) = ((cx - r).max(0.0) as usize, (cx + r).ceil() as usize);
        for y in y0..y1.min(height) {
            for x in x0..x1.min(width) {
                let (dx, dy) = (x as f64 + 0.5 - cx, y as f64 + 0.5 - cy);
                if dx * dx + dy * dy <= r * r {
                    pic.set_rgb(x, y, c);
                }
            }
        }
    };
    disc(0.52, 0.45, 0.07, WOOD);
    disc(0.06, 0.50, 0.025, PLANT);
    disc(0.50, 0.88, 0.025, PLANT);
    disc(0.72, 0.30, 0.03, PLANT);
    pic
}
