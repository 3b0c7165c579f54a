//! The room pictures and generated workspaces of seed 000.
//!
//! - `cargo xtask rooms`: draws the Table 2 room (`scenarios/maps/room_960x640.png`, and a
//!   `.pgm` of it for the OMPL peer) with [`harness::draw_room`].
//!   The one fitted size (the dining table's depth) is chosen by bisection so that the
//!   room's shortest safe path is 1.10 x the straight line, as the paper's 6009.30 mm is.
//! - `cargo xtask table4`: generates the Table 4 workspaces (three picture sizes, three
//!   obstacle counts each, three nested layouts per size) with a seeded RNG and writes them
//!   as scenario files whose furniture is listed in full, so the maps never depend on the
//!   RNG crate's version.

use std::path::{Path, PathBuf};

use anyhow::Context;
use harness::{
    Claim, ClaimKind, Furniture, Limits, MapSpec, PlannerConfig, PlannerSpec, Published, Scenario,
    Source, draw_room,
};
use rand::{Rng, SeedableRng};

const WOOD: [u8; 3] = [92, 58, 30];
const SOFA: [u8; 3] = [40, 52, 90];
const SHELF: [u8; 3] = [60, 60, 60];
const PLANT: [u8; 3] = [30, 90, 40];
const CHAIR: [u8; 3] = [70, 40, 40];

/// Table 2's start and goal (seed 000, 5.3.1), mm from the picture's top-left corner.
const TABLE2_START_MM: (f64, f64) = (74.0, 1953.0);
const TABLE2_GOAL_MM: (f64, f64) = (5501.0, 1308.0);

/// The paper's Table 2 path length over the straight start-goal line: 6009.30 mm over
/// 5465.2 mm.
pub const TABLE2_RATIO: f64 = 1.10;

/// The Table 2 room of seed 000: 960 x 640 px (6.34 mm/px, 6.09 x 4.06 m) with eleven
/// pieces of furniture, each its own obstacle component (Table 4's times put the Table 2
/// room, 960 x 640 px, between its 10- and 15-obstacle rows, nearer 10: 2.35 s against
/// 2.01 s and 3.23 s). Start (74, 1953) mm and goal (5501, 1308) mm, about (12, 308) px
/// and (868, 206) px, y down, are left in the open. The furniture is ours (the paper's
/// picture was lost with its figures); one size is fitted: `half_depth`, the half depth
/// of the dining table that stands across the straight start-goal line, so that the
/// shortest safe path is 1.10 x the straight line as the paper's 6009.30 mm is
/// ([`fit_table2`]).
fn room_960x640(half_depth: f64) -> Vec<Furniture> {
    let r = |cx, cy, hx, hy, rgb| Furniture::Rect {
        cx,
        cy,
        hx,
        hy,
        deg: 0.0,
        rgb,
    };
    let d = |cx, cy, r, rgb| Furniture::Disc { cx, cy, r, rgb };
    vec![
        // shelves along the top and bottom walls
        r(170.0, 22.0, 120.0, 20.0, SHELF),
        r(560.0, 618.0, 150.0, 20.0, SHELF),
        // sofa in the lower-left corner and a low table in front of it
        r(150.0, 560.0, 110.0, 40.0, SOFA),
        r(180.0, 440.0, 50.0, 25.0, WOOD),
        // an armchair near the start, below the line
        r(120.0, 170.0, 35.0, 35.0, CHAIR),
        // the dining table across the straight line (half depth fitted)
        r(450.0, 262.0, 55.0, half_depth, WOOD),
        // a round side table and a cabinet on the right
        d(700.0, 420.0, 45.0, WOOD),
        r(690.0, 80.0, 40.0, 60.0, SHELF),
        // plants near the goal side and in the lower-right corner
        d(905.0, 60.0, 28.0, PLANT),
        d(890.0, 560.0, 35.0, PLANT),
        // a desk along the right wall below the goal
        r(920.0, 360.0, 30.0, 70.0, WOOD),
    ]
}

/// The shortest safe path of a room and its obstacle components: the picture through the
/// seed-000 pipeline (threshold 100, rectangles, 20 px band), Theta* on the safe map
/// from `start` to `goal` (px, y down). Returns (length px, straight px, components).
pub fn shortest_safe(
    width: usize,
    height: usize,
    furniture: &[Furniture],
    start: (f64, f64),
    goal: (f64, f64),
) -> anyhow::Result<(f64, f64, usize)> {
    let picture = draw_room(width, height, furniture);
    let pipeline = envmap::Pipeline {
        threshold: 100,
        invert: false,
        rectangles: true,
        safety_radius: 20.0,
    };
    let out = pipeline.run(&picture)?;
    let map = out.map.avoiding_risk();
    let h = height as f64;
    let s = hyplan_core::Point2::new(start.0, h - start.1);
    let g = hyplan_core::Point2::new(goal.0, h - goal.1);
    let query = hyplan_core::Query::new(s, hyplan_core::Goal::Point(g));
    // The original (eager) Theta*: the rooms were fitted with its lengths.
    let theta = search::ThetaStar {
        lazy: false,
        ..search::ThetaStar::default()
    };
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(0);
    let plan = theta
        .plan(&map, &query, &mut rng)
        .map_err(|e| anyhow::anyhow!("no safe path: {e}"))?;
    Ok((plan.length(), (g - s).norm(), out.components.len()))
}

/// Fits the Table 2 room: bisection on the dining table's half depth (px) until the
/// shortest safe path (Theta* on the safe map) is [`TABLE2_RATIO`] x the straight line.
/// Returns the half depth, the length and straight distance (px) and the components.
pub fn fit_table2() -> anyhow::Result<(f64, f64, f64, usize)> {
    let px = |(x, y): (f64, f64)| (x / MM_PER_PX, y / MM_PER_PX);
    let (s, g) = (px(TABLE2_START_MM), px(TABLE2_GOAL_MM));
    let ratio = |hd: f64| -> anyhow::Result<(f64, f64, f64, usize)> {
        let (len, straight, comps) = shortest_safe(960, 640, &room_960x640(hd), s, g)?;
        Ok((len / straight, len, straight, comps))
    };
    // The detour grows with the depth: 30 px leaves a short way round, 220 px a long one.
    let (mut lo, mut hi) = (30.0_f64, 220.0_f64);
    for _ in 0..14 {
        let mid = 0.5 * (lo + hi);
        if ratio(mid)?.0 < TABLE2_RATIO {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    // Whole pixels keep the picture and the scenario readable.
    let hd = (0.5 * (lo + hi)).round();
    let (_, len, straight, comps) = ratio(hd)?;
    Ok((hd, len, straight, comps))
}

/// Writes the Table 2 room into `dir`: `room_960x640.png` (RGB) and `room_960x640.pgm`
/// (grey, for the OMPL peer), with the fitted table depth; prints how it was fitted.
pub fn write_rooms(dir: &Path) -> anyhow::Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    let (hd, len, straight, comps) = fit_table2()?;
    println!(
        "Table 2 room: table half depth fitted to {hd} px; shortest safe path (Theta*) {:.1} px = {:.1} mm = {:.4} x the straight line ({:.1} mm; paper 6009.30 mm = 1.0996 x); {comps} obstacle components",
        len,
        len * MM_PER_PX,
        len / straight,
        straight * MM_PER_PX
    );
    let picture = draw_room(960, 640, &room_960x640(hd));
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

/// GA-PCHIP's parameters in mm on seed 000's rooms (defaults otherwise): violation probes
/// every 4 px, curve samples every pixel.
/// GA-PCHIP's spacings for the Table 4 rooms, in millimetres.
fn ga_pchip_mm() -> hybrid::GaPchip {
    hybrid::GaPchip {
        probe_spacing: 25.36,
        curve_spacing: 6.34,
        ..hybrid::GaPchip::default()
    }
}

/// How a_max was fitted (the report marks it).
pub const FITTED_A_MAX: &str = "a_max = 115 mm/s^2, fitted so that the trapezoid profile T = L / v_max + v_max / a_max gives the paper's Table 2 transfer time 41.37 s for its 6009.30 mm at v_max 150 mm/s (150^2 / (150 x 41.37 - 6009.30) = 114.7); transfer times are therefore a function of length, not an independent measurement";

/// Layouts per Table 4 cell (picture size and obstacle count).
pub const LAYOUTS: [char; 3] = ['a', 'b', 'c'];

/// Draws `n` pieces of furniture at random, at least 60 px apart (two 20 px bands leave a
/// 20 px corridor) and 60 px from the start `s` and the goal `g` (px, y down). Piece k
/// depends only on the draws before it, so the first m pieces of a room of n are the room
/// of m.
fn random_furniture(
    rng: &mut impl Rng,
    w: usize,
    h: usize,
    n: usize,
    s: (f64, f64),
    g: (f64, f64),
) -> Option<Vec<Furniture>> {
    let palette = [WOOD, SOFA, SHELF, PLANT, CHAIR];
    let mut out: Vec<Furniture> = Vec::new();
    for k in 0..n {
        let placed = (0..2000).find_map(|_| {
            let rgb = palette[k % palette.len()]; // Whole pixels and degrees: the scenario files stay readable.
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
            (apart && gap(s) >= 60.0 && gap(g) >= 60.0).then_some(piece)
        })?;
        out.push(placed);
    }
    Some(out)
}

/// Generates the Table 4 scenarios into `dir`: for each picture size, three layouts
/// (`a`, `b`, `c`), each a room drawn once with the largest obstacle count of its size and
/// cut to the smaller counts (the room of 10 pieces is the room of 15 without its last 5:
/// nested, so a trend over the counts compares furniture added to one room, not unrelated
/// rooms). Each layout has its own start and goal (the paper: "different numbers of
/// cameras with different [start and goal] positions"), drawn once per layout near the
/// left and right edges and kept for its three counts. A layout is redrawn until its
/// largest room has a safe path (grid A* on its safe map; the smaller rooms then have one
/// too).
pub fn write_table4(dir: &Path) -> anyhow::Result<Vec<PathBuf>> {
    // The old single-layout files are replaced.
    for e in std::fs::read_dir(dir)?.filter_map(Result::ok) {
        let name = e.file_name().to_string_lossy().to_string();
        if name.starts_with("000-table4-") && name.ends_with(".ron") {
            std::fs::remove_file(e.path())?;
        }
    }
    let mut files = Vec::new();
    for (w, h, rows) in TABLE4 {
        let most = rows[2].0;
        for (li, letter) in LAYOUTS.iter().enumerate() {
            let seed = (w * 1000 + li) as u64;
            let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
            let (wf, hf) = (w as f64, h as f64);
            let (start, goal, furniture) = (0..100)
                .find_map(|_| {
                    let mut at = |x0: f64, x1: f64| {
                        (
                            rng.random_range(x0 * wf..x1 * wf).round(),
                            rng.random_range(0.15 * hf..0.85 * hf).round(),
                        )
                    };
                    let (s, g) = (at(0.02, 0.08), at(0.92, 0.98));
                    let furniture = random_furniture(&mut rng, w, h, most, s, g)?;
                    shortest_safe(w, h, &furniture, s, g).ok()?;
                    Some((s, g, furniture))
                })
                .with_context(|| format!("{w}x{h} layout {letter}: no safe path in 100 draws"))?;
            for (n, ours_paper, ga_paper) in rows {
                let name = format!("000-table4-{w}x{h}-{n}-{letter}");
                let path = dir.join(format!("{name}.ron"));
                let mut claims = vec![Claim {
                    text: format!(
                        "at {w} x {h} px with {n} obstacles, RRT-A*-BT is faster than GA-PCHIP (paper {ours_paper} s vs {ga_paper} s; layouts a-c pooled)"
                    ),
                    metric: "cpu_time_s".into(),
                    order: vec!["RRT-A*-BT".into(), "GA-PCHIP".into()],
                    across: vec![format!("000-table4-{w}x{h}-{n}")],
                    kind: ClaimKind::Measured,
                }];
                claims.retain(|_| *letter == 'a');
                // The trends sit in layout a of the largest count; they pool the layouts.
                if n == most && *letter == 'a' {
                    for (planner, paper) in [
                        ("RRT-A*-BT", rows.map(|r| r.1)),
                        ("GA-PCHIP", rows.map(|r| r.2)),
                    ] {
                        claims.push(Claim {
                            text: format!(
                                "at {w} x {h} px, time grows with the number of obstacles (paper {} s; nested rooms, layouts a-c pooled)",
                                paper.map(|t| t.to_string()).join(" < ")
                            ),
                            metric: "cpu_time_s".into(),
                            order: vec![planner.into()],
                            across: rows
                                .iter()
                                .map(|r| format!("000-table4-{w}x{h}-{}", r.0))
                                .collect(),
                            kind: ClaimKind::Measured,
                        });
                    }
                }
                let scenario = table4_scenario(
                    &name,
                    w,
                    h,
                    n,
                    furniture[..n].to_vec(),
                    (start, goal),
                    seed * 100 + n as u64,
                    ours_paper,
                    ga_paper,
                    claims,
                );
                let text = harness::ron_options()
                    .to_string_pretty(&scenario, ron::ser::PrettyConfig::default())?;
                let header = format!(
                    "// Seed 000 Table 4: a generated {w} x {h} px workspace with {n} obstacles, layout {letter}.\n\
                     // Written by `cargo xtask table4` (layout seed {seed}); nested: the first {n} pieces \
                     of layout {letter}'s {most}-piece room. The workspaces are ours, the sizes, counts and times the paper's.\n"
                );
                std::fs::write(&path, header + &text + "\n")
                    .with_context(|| format!("writing {}", path.display()))?;
                files.push(path);
            }
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
    (start, goal): ((f64, f64), (f64, f64)),
    seed: u64,
    ours_paper: f64,
    ga_paper: f64,
    claims: Vec<Claim>,
) -> Scenario {
    let px = |(x, y): (f64, f64)| {
        (
            (x * MM_PER_PX * 100.0).round() / 100.0,
            (y * MM_PER_PX * 100.0).round() / 100.0,
        )
    };
    let published = |planner: &str, value: f64| Published {
        planner: planner.into(),
        metric: "time_s".into(),
        value,
        note: "s, mean of many runs".into(),
        unit_scale: 1.0,
        printed: format!("{value:.2}"),
    };
    Scenario {
        name: name.into(),
        source: Source {
            seed_file: "000_9b224721fe327833.txt".into(),
            experiment: format!("Table 4, {w}x{h} px, {n} obstacles"),
        },
        description: format!(
            "A generated {w} x {h} px room with {n} pieces of furniture (ours, nested in the layout's larger rooms), 6.34 mm/px, rectangles and a 20 px band; start and goal drawn per layout near the left and right edges."
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
        start: px(start),
        goal: px(goal),
        goal_radius: 126.8,
        avoid_risk: true,
        limits: Some(Limits {
            v_max: 150.0,
            omega_max: 1.0,
            a_max: 115.0,
        }),
        runs: 30,
        quick_runs: 2,
        base_seed: seed,
        planners: vec![
            PlannerSpec {
                label: Some("RRT-A*-BT".into()),
                ..PlannerSpec::new(PlannerConfig::RrtAstarBt(hybrid::RrtAstarBt {
                    step: 253.6,
                    goal_radius: 126.8,
                    closed_radius: Some(63.4),
                    curve_spacing: 6.34,
                    budget: hyplan_core::Budget::iterations(10_000),
                    ..hybrid::RrtAstarBt::default()
                }))
            },
            PlannerSpec {
                label: Some("GA-PCHIP".into()),
                ..PlannerSpec::new(PlannerConfig::GaPchip(ga_pchip_mm()))
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
            "furniture (seeded generator, nested)".into(),
            "start and goal (drawn per layout)".into(),
            "30 runs per layout, 3 layouts per cell".into(),
            "GA-PCHIP's GA (docs/papers/000-rrt-astar-bt.md)".into(),
            "a_max 115 mm/s^2".into(),
        ],
        fitted: vec![FITTED_A_MAX.into()],
        baseline: Some("GA-PCHIP".into()),
    }
}
