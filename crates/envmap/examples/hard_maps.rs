//! Writes the generated hard maps as PNG pictures (black obstacles on white) and prints,
//! for each, the suggested start and goal in the picture's frame (column, row from the
//! top), ready for `hyplan plan --map FILE --start X,Y --goal X,Y`.
//!
//! ```text
//! cargo run --release -p envmap --example hard_maps -- OUT_DIR [STEP] [SEED]
//! ```
//!
//! Writes `OUT_DIR/KIND.png` for every [`HardMap`] kind scaled to `STEP` (default 10),
//! plus the three maps of issue 13's report: `report-maze.png` (10-pixel corridors),
//! `report-spiral.png` (10-pixel corridors) and `report-floor-plan.png` (1732 x 1732, about
//! 3 megapixels, 60-pixel doors for `--step 40`).

use std::path::PathBuf;

use envmap::{Generated, HardMap};
use envmap::{Picture, write_picture};
use hyplan_core::Zone;
use rand::SeedableRng;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let dir = PathBuf::from(
        args.next()
            .ok_or("usage: hard_maps OUT_DIR [STEP] [SEED]")?,
    );
    let step: f64 = args.next().map_or(Ok(10.0), |s| s.parse())?;
    let seed: u64 = args.next().map_or(Ok(1), |s| s.parse())?;
    std::fs::create_dir_all(&dir)?;
    let mut maps: Vec<(String, Generated)> = Vec::new();
    for kind in HardMap::ALL {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        maps.push((kind.name().to_string(), kind.generate(step, &mut rng)));
    }
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    maps.push(("report-maze".into(), envmap::maze(16, 16, 10, 4, &mut rng)));
    maps.push(("report-spiral".into(), envmap::spiral(8, 10, 4, &mut rng)));
    maps.push((
        "report-floor-plan".into(),
        envmap::floor_plan(1732, 1732, 60, 6, &mut rng),
    ));
    for (name, g) in &maps {
        let (w, h) = (g.map.width(), g.map.height());
        let mut data = vec![255_u8; w * h];
        for j in 0..h {
            for i in 0..w {
                if g.map.cell_zone(i, j) == Zone::Forbidden {
                    data[(h - 1 - j) * w + i] = 0;
                }
            }
        }
        let path = dir.join(format!("{name}.png"));
        let picture = Picture::grey(w, h, data).ok_or("picture size")?;
        write_picture(&picture, &path)?;
        // Picture frame: column = x, row from the top = height - y.
        println!(
            "{name} {w}x{h} --start {},{} --goal {},{}",
            g.start.x,
            h as f64 - g.start.y,
            g.goal.x,
            h as f64 - g.goal.y
        );
    }
    Ok(())
}
