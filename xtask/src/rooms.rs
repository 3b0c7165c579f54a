//! The room pictures and generated workspaces of seed 000.
//!
//! - `cargo xtask rooms`: draws the Table 2 room (`scenarios/maps/room_960x640.png`, and a
//!   `.pgm` of it for the OMPL peer) with [`harness::draw_room`].
//! - `cargo xtask table4`: generates the nine Table 4 workspaces (three picture sizes, three
//!   obstacle counts each) with a seeded RNG and writes them as scenario files whose
//!   furniture is listed in full, so the maps never depend on the RNG crate's version.

use std::path::{Path, PathBuf};

use anyhow::Context;
use harness::{
    Claim, Furniture, Limits, MapSpec, PlannerSpec, Published, Scenario, Source, draw_room,
};
use rand::{Rng, SeedableRng};

const WOOD: [u8; 3] = [92, 58, 30];
const SOFA: [u8; 3] = [40, 52, 90];
const SHELF: [u8; 3] = [60, 60, 60];
const PLANT: [u8; 3] = [30, 90, 40];
const CHAIR: [u8; 3] = [70, 40, 40];

/// The Table 2 room of seed 000: 960 x 640 px (6.34 mm/px, 6.09 x 4.06 m), cluttered, with
/// the start (74, 1953) mm and the goal (5501, 1308) mm (about (12, 308) px and
/// (868, 206) px, y down) left in the open. The furniture is ours: the paper's picture
/// was lost with its figures.
fn room_960x640() -> Vec<Furniture> {
    let r = |cx, cy, hx, hy, deg, rgb| Furniture::Rect {
        cx,
        cy,
        hx,
        hy,
        deg,
        rgb,
    };
    let d = |cx, cy, r, rgb| Furniture::Disc { cx, cy, r, rgb };
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

/// Writes the Table 2 room into `dir`: `room_960x640.png` (RGB) and `room_960x640.pgm`
/// (grey, for the OMPL peer).
pub fn write_rooms(dir: &Path) -> anyhow::Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    let picture = draw_room(960, 640, &room_960x640());
    let rgb = image::RgbImage::from_raw(960, 640, picture.data().to_vec())
        .context("picture buffer size")?;
    let png = dir.join("room_960x640.png");
    rgb.save(&png)
        .with_context(|| format!("writing {}", png.display()))?;
    let pgm = dir.join("room_960x640.pgm");
    image::DynamicImage::ImageRgb8(rgb)
        .to_luma8()
        .save(&pgm)
        .with_context(|| format!("writing {}", pgm.display()))?;
    Ok(vec![png, pgm])
}

/// Seed 000 Table 4: (width, height, obstacle counts, the paper's RRT-A*-BT and GA-PCHIP
/// times in s for each count).
/// One Table 4 row: obstacle count, the paper's RRT-A*-BT time and GA-PCHIP time (s).
type Table4Row = (usize, f64, f64);

const TABLE4: [(usize, usize, [Table4Row; 3]); 3] = [
    (
        640,
        480,
        [(5, 1.25, 5.60), (10, 2.87, 6.30), (15, 3.99, 7.50)],
    ),
    (
        960,
        640,
        [(10, 2.01, 7.42), (15, 3.23, 8.74), (20, 4.62, 9.06)],
    ),
    (
        1280,
        960,
        [(15, 4.12, 10.30), (20, 4.24, 10.56), (25, 5.73, 11.26)],
    ),
];

/// Millimetres per pixel (seed 000 section 5.1).
const MM_PER_PX: f64 = 6.34;

/// Start and goal of Table 2 as fractions of the picture (x, y down), reused for Table 4.
const START_FRAC: (f64, f64) = (0.0122, 0.481);
const GOAL_FRAC: (f64, f64) = (0.904, 0.322);

/// Draws `n` pieces of furniture at random, at least 60 px apart (two 20 px bands leave a
/// 20 px corridor) and 60 px from the start and the goal.
fn random_furniture(rng: &mut impl Rng, w: usize, h: usize, n: usize) -> Option<Vec<Furniture>> {
    let palette = [WOOD, SOFA, SHELF, PLANT, CHAIR];
    let (sx, sy) = (START_FRAC.0 * w as f64, START_FRAC.1 * h as f64);
    let (gx, gy) = (GOAL_FRAC.0 * w as f64, GOAL_FRAC.1 * h as f64);
    let mut out: Vec<Furniture> = Vec::new();
    for k in 0..n {
        let placed = (0..2000).find_map(|_| {
            let rgb = palette[k % palette.len()];
            // Whole pixels and degrees: the scenario files stay readable.
            let mut draw = |lo: f64, hi: f64| rng.random_range(lo..hi).round();
            let (cx, cy) = (draw(0.0, w as f64), draw(0.0, h as f64));
            let piece = if draw(0.0, 1.0) == 0.0 && draw(0.0, 1.0) == 0.0 {
                Furniture::Disc {
                    cx,
                    cy,
                    r: draw(20.0, 70.0),
                    rgb,
                }
            } else {
                let deg = if draw(0.0, 1.0) == 0.0 && draw(0.0, 1.0) == 0.0 {
                    draw(-30.0, 30.0)
                } else {
                    0.0
                };
                Furniture::Rect {
                    cx,
                    cy,
                    hx: draw(15.0, 100.0),
                    hy: draw(15.0, 100.0),
                    deg,
                    rgb,
                }
            };
            let gap = |(x, y): (f64, f64)| (x - cx).hypot(y - cy) - piece.reach();
            let apart = out.iter().all(|o| gap(o.center()) - o.reach() >= 60.0);
            (apart && gap((sx, sy)) >= 60.0 && gap((gx, gy)) >= 60.0).then_some(piece)
        })?;
        out.push(placed);
    }
    Some(out)
}

/// Generates the nine Table 4 scenarios into `dir`, each checked to have a safe path
/// (grid A* on its zone map); redraws until it has.
pub fn write_table4(dir: &Path) -> anyhow::Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    for (w, h, rows) in TABLE4 {
        for (n, ours_paper, ga_paper) in rows {
            let seed = (w * 1000 + n) as u64;
            let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
            let name = format!("000-table4-{w}x{h}-{n}");
            let path = dir.join(format!("{name}.ron"));
            let scenario = (0..100)
                .find_map(|_| {
                    let furniture = random_furniture(&mut rng, w, h, n)?;
                    // The last workspace of each picture size carries the paper's trend:
                    // time grows with the number of obstacles.
                    let claims = if n == rows[2].0 {
                        vec![Claim {
                            text: format!(
                                "at {w} x {h} px, time grows with the number of obstacles"
                            ),
                            metric: "time_s".into(),
                            order: vec!["RRT-A*-BT".into()],
                            across: rows
                                .iter()
                                .map(|r| format!("000-table4-{w}x{h}-{}", r.0))
                                .collect(),
                        }]
                    } else {
                        Vec::new()
                    };
                    let s = table4_scenario(
                        &name, w, h, n, furniture, seed, ours_paper, ga_paper, claims,
                    );
                    let world = s.build_world(dir, &path).ok()?;
                    let astar = PlannerSpec {
                        name: "astar".into(),
                        label: None,
                        params: Default::default(),
                        smoothing: None,
                    };
                    let planner = harness::build_planner(&astar).ok()?;
                    let mut r = rand_chacha::ChaCha8Rng::seed_from_u64(0);
                    planner.plan(&world.map, &world.query, &mut r).ok()?;
                    Some(s)
                })
                .with_context(|| format!("{name}: no workspace with a safe path in 100 draws"))?;
            let text = ron::ser::to_string_pretty(&scenario, ron::ser::PrettyConfig::default())?;
            let header = format!(
                "// Seed 000 Table 4: a generated {w} x {h} px workspace with {n} obstacles.\n\
                 // Written by `cargo xtask table4` (seed {seed}); the workspaces are ours, the \
                 sizes, counts and times the paper's.\n"
            );
            std::fs::write(&path, header + &text + "\n")
                .with_context(|| format!("writing {}", path.display()))?;
            files.push(path);
        }
    }
    Ok(files)
}

#[allow(clippy::too_many_arguments)]
fn table4_scenario(
    name: &str,
    w: usize,
    h: usize,
    n: usize,
    furniture: Vec<Furniture>,
    seed: u64,
    ours_paper: f64,
    ga_paper: f64,
    claims: Vec<Claim>,
) -> Scenario {
    let px = |(fx, fy): (f64, f64)| {
        (
            (fx * w as f64 * MM_PER_PX * 100.0).round() / 100.0,
            (fy * h as f64 * MM_PER_PX * 100.0).round() / 100.0,
        )
    };
    let published = |planner: &str, value: f64| Published {
        planner: planner.into(),
        metric: "time_s".into(),
        value,
        note: "s, mean of many runs".into(),
        unit_scale: 1.0,
    };
    Scenario {
        name: name.into(),
        source: Source {
            seed_file: "000_9b224721fe327833.txt".into(),
            experiment: format!("Table 4, {w}x{h} px, {n} obstacles"),
        },
        description: format!(
            "A generated {w} x {h} px room with {n} pieces of furniture (ours), 6.34 mm/px, rectangles and a 20 px band; start and goal at Table 2's relative positions."
        ),
        map: MapSpec::Room {
            width: w,
            height: h,
            furniture,
            threshold: 100,
            rectangles: true,
            safety_radius_px: 20.0,
            resolution: MM_PER_PX,
        },
        units: "mm".into(),
        start: px(START_FRAC),
        goal: px(GOAL_FRAC),
        goal_radius: 126.8,
        avoid_risk: true,
        limits: Some(Limits {
            v_max: 150.0,
            omega_max: 1.0,
            a_max: 115.0,
        }),
        runs: 100,
        quick_runs: 5,
        base_seed: seed,
        planners: vec![
            PlannerSpec {
                name: "rrt-astar-bt".into(),
                label: Some("RRT-A*-BT".into()),
                params: [
                    ("step".to_string(), 253.6),
                    ("goal_radius".to_string(), 126.8),
                    ("closed_radius".to_string(), 63.4),
                    ("curve_spacing".to_string(), 6.34),
                    ("max_iterations".to_string(), 10000.0),
                ]
                .into_iter()
                .collect(),
                smoothing: None,
            },
            PlannerSpec {
                name: "rrt".into(),
                label: Some("RRT".into()),
                params: [
                    ("step".to_string(), 253.6),
                    ("goal_bias".to_string(), 0.05),
                    ("max_iterations".to_string(), 10000.0),
                ]
                .into_iter()
                .collect(),
                smoothing: None,
            },
        ],
        published: vec![
            published("RRT-A*-BT", ours_paper),
            published("GA-PCHIP", ga_paper),
        ],
        claims,
        from_paper: vec![
            "picture size".into(),
            "obstacle count".into(),
            "scale 6.34 mm/px".into(),
            "20 px band".into(),
            "planner parameters".into(),
        ],
        reconstructed: vec![
            "furniture (seeded generator)".into(),
            "start and goal (Table 2's relative positions)".into(),
            "100 runs".into(),
        ],
    }
}
