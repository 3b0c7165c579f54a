//! Seeded generators of hard maps: mazes, spirals, bug traps, narrow passages, large floor
//! plans, random clutter and grids of rooms.
//!
//! Every generator returns a [`Generated`]: a [`GridMap`] of Free and Forbidden cells
//! (resolution 1, origin (0, 0): one world unit per cell, the frame of a picture loaded
//! by [`load_map`](crate::load_map)) with a suggested start and goal at free cell centres,
//! connected through the free cells. Add a high-risk band with [`with_risk_band`].
//!
//! All randomness comes from the `rng` passed in (`&mut impl rand::Rng`), so a seeded
//! generator (`rand_chacha::ChaCha8Rng::seed_from_u64(seed)`) gives the same map, cell for
//! cell, on every run and platform. Sizes are in cells; every size argument is clamped to
//! a sensible minimum (corridors and walls at least one cell), so no argument panics.
//!
//! [`HardMap`] names the kinds, with one default recipe each scaled to a planner's step
//! ([`HardMap::generate`]), for suites that run every planner on every kind.
//!
//! ```
//! use envmap::HardMap;
//! use hyplan_core::Workspace;
//! use rand::SeedableRng;
//! let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
//! let g = envmap::maze(8, 6, 15, 3, &mut rng);
//! assert!(g.map.is_free(g.start) && g.map.is_free(g.goal));
//! // Same seed, same map.
//! let again = envmap::maze(8, 6, 15, 3, &mut rand_chacha::ChaCha8Rng::seed_from_u64(7));
//! assert_eq!(g.map, again.map);
//! let spiral = HardMap::Spiral.generate(10.0, &mut rng);
//! assert!(spiral.map.is_free(spiral.goal));
//! ```

use hyplan_core::{Goal, Point2, Query, Zone};
use rand::Rng;

mod canvas;

use canvas::{Canvas, Lattice, connected, lattice_neighbours, nearest_free};

use crate::{GridMap, Mask, distance_transform, zones};

/// A generated map with a suggested query.
#[derive(Debug, Clone, PartialEq)]
pub struct Generated {
    /// The map: Free and Forbidden cells, resolution 1, origin (0, 0).
    pub map: GridMap,
    /// A free cell centre to start from.
    pub start: Point2,
    /// A free cell centre to reach, connected to `start` through free cells.
    pub goal: Point2,
}

/// The kinds of hard maps, each with a default recipe scaled to a planner's step.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum HardMap {
    /// [`maze`]: a perfect maze, corridors 1.5 steps wide.
    Maze,
    /// [`spiral`]: a room inside concentric walls, corridors 1.5 steps wide.
    Spiral,
    /// [`bug_trap`]: the start inside a bottle whose neck faces away from the goal.
    BugTrap,
    /// [`narrow_passage`]: a thick wall with one tunnel half a step wide.
    NarrowPassage,
    /// [`floor_plan`]: 2000 x 2000 cells of rooms, corridors and doors.
    FloorPlan,
    /// [`clutter`]: random rectangles over about 30 % of the area.
    Clutter,
    /// [`rooms`]: a grid of rooms joined by doors along a random spanning tree.
    Rooms,
}

/// The risk band of the hard-map suite's maps, cells (`--safety-radius 2`).
pub const SUITE_BAND: f64 = 2.0;

/// The goal disc's radius in the hard-map suite, cells (`--goal-radius 2`).
pub const SUITE_GOAL_RADIUS: f64 = 2.0;

impl HardMap {
    /// Every kind, in declaration order.
    pub const ALL: [HardMap; 7] = [
        HardMap::Maze,
        HardMap::Spiral,
        HardMap::BugTrap,
        HardMap::NarrowPassage,
        HardMap::FloorPlan,
        HardMap::Clutter,
        HardMap::Rooms,
    ];

    /// The kind's name in kebab case (`maze`, `bug-trap`, `floor-plan`, ...).
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            HardMap::Maze => "maze",
            HardMap::Spiral => "spiral",
            HardMap::BugTrap => "bug-trap",
            HardMap::NarrowPassage => "narrow-passage",
            HardMap::FloorPlan => "floor-plan",
            HardMap::Clutter => "clutter",
            HardMap::Rooms => "rooms",
        }
    }

    /// The step the hard-map suite plans with on this kind: 40 cells on the 2000 x 2000
    /// floor plan (the step of the report behind issue 13), `small` on the others.
    #[must_use]
    pub fn suite_step(self, small: f64) -> f64 {
        if self == HardMap::FloorPlan {
            40.0
        } else {
            small
        }
    }

    /// The hard-map suite's planning problem on this kind, as `hyplan plan --step STEP
    /// --safety-radius 2 --goal-radius 2` poses it: the [`generate`](HardMap::generate)d
    /// map with a [`SUITE_BAND`]-cell risk band ([`with_risk_band`]; only Forbidden
    /// blocks), and the query from its start to a goal disc of radius
    /// [`SUITE_GOAL_RADIUS`] round its goal. Shared by the suite's test and its benchmark.
    pub fn suite_problem<R: Rng + ?Sized>(self, step: f64, rng: &mut R) -> (GridMap, Query) {
        let Generated { map, start, goal } = self.generate(step, rng);
        (
            with_risk_band(&map, SUITE_BAND),
            Query::new(start, Goal::disc(goal, SUITE_GOAL_RADIUS)),
        )
    }

    /// The kind's default map for a planner of step `step` (world units = cells, clamped
    /// to at least 1): corridors and doors 1.5 steps wide, the narrow passage half a
    /// step wide (at least 6 cells, so that a 2-cell risk band leaves a safe core), walls 3
    /// cells thick. Sizes: maze 12 x 12 maze cells,
    /// spiral 5 rings, bug trap 40 steps a side, narrow passage 40 x 24 steps, clutter 50 x
    /// 50 steps, rooms 5 x 5 rooms of 6 steps; the floor plan is 2000 x 2000 cells
    /// whatever the step (doors 1.5 steps wide).
    pub fn generate<R: Rng + ?Sized>(self, step: f64, rng: &mut R) -> Generated {
        let s = if step.is_finite() { step.max(1.0) } else { 1.0 };
        let corridor = (1.5 * s).round() as usize;
        let cells = |k: f64| (k * s).round() as usize;
        match self {
            HardMap::Maze => maze(12, 12, corridor, 3, rng),
            HardMap::Spiral => spiral(5, corridor, 3, rng),
            HardMap::BugTrap => bug_trap(cells(40.0), corridor, 3, rng),
            HardMap::NarrowPassage => narrow_passage(
                cells(40.0),
                cells(24.0),
                ((0.5 * s).round() as usize).max(6),
                cells(2.0),
                rng,
            ),
            HardMap::FloorPlan => floor_plan(2000, 2000, corridor, 4, rng),
            HardMap::Clutter => clutter(cells(50.0), cells(50.0), 0.3, corridor, rng),
            HardMap::Rooms => rooms(5, 5, cells(6.0), corridor, 3, rng),
        }
    }
}

/// A perfect maze (exactly one route between any two places) of `nx x ny` maze cells,
/// carved by a randomised depth-first search: each maze cell is a free square of
/// `corridor` cells, walls are `wall` cells thick, and the outer border is walled. The
/// map is `n * (corridor + wall) + wall` cells a side. Start: the centre of the lower-left
/// maze cell; goal: the centre of the upper-right one (a long winding route).
pub fn maze<R: Rng + ?Sized>(
    nx: usize,
    ny: usize,
    corridor: usize,
    wall: usize,
    rng: &mut R,
) -> Generated {
    let lattice = Lattice::new(nx, ny, corridor, 1, wall);
    let (nx, ny, c, pitch) = (lattice.nx, lattice.ny, lattice.inner, lattice.pitch());
    let mut canvas = lattice.carve();
    // Randomised depth-first search over the maze cells, knocking down walls.
    let mut visited = vec![false; nx * ny];
    let mut stack = vec![(0_usize, 0_usize)];
    visited[0] = true;
    while let Some(&(i, j)) = stack.last() {
        let mut next = lattice_neighbours(i, j, nx, ny);
        next.retain(|&(a, b)| !visited[b * nx + a]);
        if next.is_empty() {
            stack.pop();
            continue;
        }
        let (a, b) = next[rng.random_range(0..next.len())];
        visited[b * nx + a] = true;
        let (x0, y0) = lattice.origin(i.min(a), j.min(b));
        if a != i {
            canvas.rect(x0 + c, y0, x0 + pitch, y0 + c, false);
        } else {
            canvas.rect(x0, y0 + c, x0 + c, y0 + pitch, false);
        }
        stack.push((a, b));
    }
    lattice.finish(canvas)
}

/// A room inside a spiral: `rings` concentric square walls (`wall` cells thick,
/// `corridor` cells apart) around a central room of `2 * corridor` cells, each ring open
/// by one `corridor`-wide gap. Consecutive gaps sit on opposite sides (which side first is
/// drawn from `rng`), so the route winds half a turn per ring. Start: outside the outer
/// ring, in the lower-left corner; goal: the centre of the room.
pub fn spiral<R: Rng + ?Sized>(
    rings: usize,
    corridor: usize,
    wall: usize,
    rng: &mut R,
) -> Generated {
    let (rings, c, w) = (rings.max(1), corridor.max(1), wall.max(1));
    let room = 2 * c;
    let size = room + 2 * rings * (c + w) + 2 * c;
    let mut canvas = Canvas::new(size, size);
    let mid = size / 2;
    let flip = rng.random_bool(0.5);
    // Outer rings first: each ring's fill clears its inside.
    for k in (0..rings).rev() {
        // Ring k (0 innermost): its inner edge is room / 2 + k (c + w) from the middle.
        let inner = room / 2 + k * (c + w);
        let (lo, hi) = (mid - inner - w, mid + inner + w);
        canvas.rect(lo, lo, hi, hi, true);
        canvas.rect(lo + w, lo + w, hi - w, hi - w, false);
        // The gap, centred on the middle of the left or right side.
        let (g0, g1) = (mid - c / 2, mid - c / 2 + c);
        if (k % 2 == 0) ^ flip {
            canvas.rect(lo, g0, lo + w, g1, false);
        } else {
            canvas.rect(hi - w, g0, hi, g1, false);
        }
    }
    canvas.finish((c / 2, c / 2), (mid, mid))
}

/// A bug trap: a square map `size` cells a side with a bottle-shaped trap around the
/// start: a hollow square of walls `wall` thick, about half the map wide, whose only
/// opening is a neck `neck` cells wide facing away from the goal, lined by inward walls
/// so that the neck is a short tunnel. The goal lies behind the trap's closed back, at a
/// random height. Growing straight towards the goal only piles nodes against the back
/// wall.
pub fn bug_trap<R: Rng + ?Sized>(size: usize, neck: usize, wall: usize, rng: &mut R) -> Generated {
    let (n, w) = (neck.max(1), wall.max(1));
    let size = size.max(4 * n + 8 * w + 8);
    let mut canvas = Canvas::new(size, size);
    let (lo, hi) = (size / 4, size - size / 4);
    // The bottle: a hollow square, open on the left by the neck.
    canvas.rect(lo, lo, hi, hi, true);
    canvas.rect(lo + w, lo + w, hi - w, hi - w, false);
    let mid = size / 2;
    let (n0, n1) = (mid - n / 2, mid - n / 2 + n);
    canvas.rect(lo, n0, lo + w, n1, false);
    // The neck's lips: short walls pointing inwards above and below the opening.
    let lip = (hi - lo) / 4;
    canvas.rect(lo + w, n1, lo + w + lip, n1 + w, true);
    canvas.rect(lo + w, n0.saturating_sub(w), lo + w + lip, n0, true);
    let start = (mid + (hi - lo) / 4, mid);
    let margin = (size - hi) / 2;
    let goal_y = rng.random_range(lo..hi);
    canvas.finish(start, (hi + margin, goal_y))
}

/// A narrow passage: a `width x height` map split by a vertical wall `thickness` cells
/// thick, crossed by one horizontal tunnel `gap` cells wide at a random height. A `gap` of
/// 0 leaves no tunnel (start and goal disconnected, for "no path" tests). Start: the
/// middle of the left part; goal: the middle of the right part.
pub fn narrow_passage<R: Rng + ?Sized>(
    width: usize,
    height: usize,
    gap: usize,
    thickness: usize,
    rng: &mut R,
) -> Generated {
    let t = thickness.max(1);
    let width = width.max(t + 4);
    let height = height.max(gap + 4);
    let mut canvas = Canvas::new(width, height);
    let x0 = (width - t) / 2;
    canvas.rect(x0, 0, x0 + t, height, true);
    if gap > 0 {
        let y = rng.random_range(1..height - gap);
        canvas.rect(x0, y, x0 + t, y + gap, false);
    }
    canvas.finish((x0 / 2, height / 2), ((x0 + t + width) / 2, height / 2))
}

/// A large floor plan, `width x height` cells (use at least 2000 x 2000 for the hard-map
/// suite): the outer walls, then a recursive division into rooms (walls `wall` cells
/// thick, each split wall pierced by one door `door` cells wide at a random place), where
/// large regions are split by a corridor (`door` to `2 * door` wide between two walls,
/// each with a door) instead of a single wall. Splits avoid the doors of the walls they
/// end on, so every room stays reachable. Rooms are not split below `max(4 * door, 100)` cells a side. Start: a free cell near the lower-left corner; goal: one near the upper-right.
pub fn floor_plan<R: Rng + ?Sized>(
    width: usize,
    height: usize,
    door: usize,
    wall: usize,
    rng: &mut R,
) -> Generated {
    let (d, w) = (door.max(1), wall.max(1));
    let min_room = (4 * d).max(100);
    let width = width.max(min_room + 2 * w);
    let height = height.max(min_room + 2 * w);
    let mut canvas = Canvas::new(width, height);
    canvas.rect(0, 0, width, w, true);
    canvas.rect(0, height - w, width, height, true);
    canvas.rect(0, 0, w, height, true);
    canvas.rect(width - w, 0, width, height, true);
    // Door spans: (vertical wall?, fixed coordinate range, span range) to keep splits off.
    let mut doors: Vec<Door> = Vec::new();
    let mut regions = vec![(w, w, width - w, height - w)];
    while let Some((x0, y0, x1, y1)) = regions.pop() {
        let (rw, rh) = (x1 - x0, y1 - y0);
        let vertical = if rw.max(rh) < 2 * min_room + w {
            continue;
        } else if rw >= 2 * min_room + w && rh >= 2 * min_room + w {
            rng.random_bool(if rw >= rh { 0.7 } else { 0.3 })
        } else {
            rw >= rh
        };
        let (a0, a1) = if vertical { (x0, x1) } else { (y0, y1) };
        let (b0, b1) = if vertical { (y0, y1) } else { (x0, x1) };
        let corridor = if a1 - a0 >= 4 * min_room {
            rng.random_range(d..=2 * d)
        } else {
            0
        };
        let span = if corridor > 0 { 2 * w + corridor } else { w };
        // A split position that keeps both sides at least min_room and clears the doors
        // in the walls at both ends of the split.
        let lo = a0 + min_room;
        let hi = a1 - min_room - span;
        let blocked_at = |p: usize| {
            doors.iter().any(|door| {
                door.vertical != vertical
                    && (door.at == b0.wrapping_sub(w) || door.at == b1)
                    && p < door.to + 1
                    && door.from < p + span + 1
            })
        };
        let mut pos = None;
        for _ in 0..32 {
            let p = rng.random_range(lo..=hi);
            if !blocked_at(p) {
                pos = Some(p);
                break;
            }
        }
        let Some(p) = pos else { continue };
        let mut put_wall = |at: usize, canvas: &mut Canvas, rng: &mut R| {
            let door_at = rng.random_range(b0 + w..b1 - d - w);
            if vertical {
                canvas.rect(at, b0, at + w, b1, true);
                canvas.rect(at, door_at, at + w, door_at + d, false);
            } else {
                canvas.rect(b0, at, b1, at + w, true);
                canvas.rect(door_at, at, door_at + d, at + w, false);
            }
            doors.push(Door {
                vertical,
                at,
                from: door_at,
                to: door_at + d,
            });
        };
        put_wall(p, &mut canvas, rng);
        let (first_end, second_start) = if corridor > 0 {
            put_wall(p + w + corridor, &mut canvas, rng);
            (p, p + span)
        } else {
            (p, p + w)
        };
        if vertical {
            regions.push((x0, y0, first_end, y1));
            regions.push((second_start, y0, x1, y1));
        } else {
            regions.push((x0, y0, x1, first_end));
            regions.push((x0, second_start, x1, y1));
        }
    }
    let start = nearest_free(&canvas, (w + d, w + d));
    let goal = nearest_free(&canvas, (width - w - d - 1, height - w - d - 1));
    canvas.finish(start, goal)
}

/// A door in a split wall: `vertical` wall at coordinate `at`, open over `from..to`.
struct Door {
    vertical: bool,
    at: usize,
    from: usize,
    to: usize,
}

/// Random clutter: a `width x height` map with axis-aligned rectangles (sides from 1 to 4
/// `clear` widths) dropped at random until about `density` (clamped to [0, 0.6]) of the
/// area is covered, none within `clear` cells of the start (lower-left) or goal
/// (upper-right). Draws continue until start and goal are connected through free cells
/// (each rectangle that would disconnect them is taken back), so the query always has a
/// solution; `clear` also bounds how narrow the gaps can get only loosely.
pub fn clutter<R: Rng + ?Sized>(
    width: usize,
    height: usize,
    density: f64,
    clear: usize,
    rng: &mut R,
) -> Generated {
    let c = clear.max(1);
    let (width, height) = (width.max(4 * c + 4), height.max(4 * c + 4));
    let density = if density.is_finite() {
        density.clamp(0.0, 0.6)
    } else {
        0.0
    };
    let mut canvas = Canvas::new(width, height);
    let start = (c, c);
    let goal = (width - 1 - c, height - 1 - c);
    let target = (density * (width * height) as f64) as usize;
    let mut covered = 0;
    let mut tries = 0;
    let near = |x0: usize, y0: usize, x1: usize, y1: usize, p: (usize, usize)| {
        p.0 + c >= x0 && p.0 < x1 + c && p.1 + c >= y0 && p.1 < y1 + c
    };
    while covered < target && tries < 10_000 {
        tries += 1;
        let (rw, rh) = (rng.random_range(c..=4 * c), rng.random_range(c..=4 * c));
        let x0 = rng.random_range(0..width - rw.min(width - 1));
        let y0 = rng.random_range(0..height - rh.min(height - 1));
        let (x1, y1) = ((x0 + rw).min(width), (y0 + rh).min(height));
        if near(x0, y0, x1, y1, start) || near(x0, y0, x1, y1, goal) {
            continue;
        }
        let before: Vec<bool> = (y0..y1)
            .flat_map(|y| (x0..x1).map(move |x| (x, y)))
            .map(|(x, y)| canvas.get(x, y))
            .collect();
        canvas.rect(x0, y0, x1, y1, true);
        if connected(&canvas, start, goal) {
            covered += before.iter().filter(|&&b| !b).count();
        } else {
            for (k, (x, y)) in (y0..y1)
                .flat_map(|y| (x0..x1).map(move |x| (x, y)))
                .enumerate()
            {
                canvas.blocked[y * width + x] = before[k];
            }
        }
    }
    canvas.finish(start, goal)
}

/// A grid of `nx x ny` square rooms, `room` cells inside, walls `wall` cells thick,
/// joined by doors `door` cells wide (at a random place along the wall) along a random
/// spanning tree of the room grid, plus one extra door per ten rooms. Start: the centre
/// of the lower-left room; goal: the centre of the upper-right room.
pub fn rooms<R: Rng + ?Sized>(
    nx: usize,
    ny: usize,
    room: usize,
    door: usize,
    wall: usize,
    rng: &mut R,
) -> Generated {
    let d = door.max(1);
    let lattice = Lattice::new(nx, ny, room, d + 2, wall);
    let (nx, ny, r, pitch) = (lattice.nx, lattice.ny, lattice.inner, lattice.pitch());
    let mut canvas = lattice.carve();
    // Random spanning tree (randomised Prim over the room grid), then extra doors.
    let mut edges: Vec<((usize, usize), (usize, usize))> = Vec::new();
    let mut inside = vec![false; nx * ny];
    inside[0] = true;
    let mut frontier: Vec<((usize, usize), (usize, usize))> = Vec::new();
    frontier.extend(
        lattice_neighbours(0, 0, nx, ny)
            .into_iter()
            .map(|n| ((0, 0), n)),
    );
    while !frontier.is_empty() {
        let (a, b) = frontier.swap_remove(rng.random_range(0..frontier.len()));
        if inside[b.1 * nx + b.0] {
            continue;
        }
        inside[b.1 * nx + b.0] = true;
        edges.push((a, b));
        frontier.extend(
            lattice_neighbours(b.0, b.1, nx, ny)
                .into_iter()
                .map(|n| (b, n)),
        );
    }
    for _ in 0..(nx * ny) / 10 {
        let (i, j) = (rng.random_range(0..nx), rng.random_range(0..ny));
        let ns = lattice_neighbours(i, j, nx, ny);
        if !ns.is_empty() {
            edges.push(((i, j), ns[rng.random_range(0..ns.len())]));
        }
    }
    for (a, b) in edges {
        let (lo, hi) = (a.min(b), a.max(b));
        let (x, y) = lattice.origin(lo.0, lo.1);
        let off = rng.random_range(0..=r - d);
        if hi.0 != lo.0 {
            canvas.rect(x + r, y + off, x + pitch, y + off + d, false);
        } else {
            canvas.rect(x + off, y + r, x + off + d, y + pitch, false);
        }
    }
    lattice.finish(canvas)
}

/// The same map with a high-risk band: every free cell whose centre lies within `radius`
/// cells (Euclidean, centre to centre, as [`zones`]) of a Forbidden cell
/// becomes [`Zone::Risk`]. The start and goal of a [`Generated`] map may fall in the band:
/// check them against the zones you plan in.
#[must_use]
pub fn with_risk_band(map: &GridMap, radius: f64) -> GridMap {
    let obstacles = Mask::from_zones_at_least(map, Zone::Forbidden);
    let banded = zones(&obstacles, &distance_transform(&obstacles), radius);
    let mut out = map.clone();
    out.zones_mut().copy_from_slice(&banded);
    out
}

/// A random pair of free cell centres of `map` (under its
/// [`blocked_from`](GridMap::blocked_from)) joined by 4-connected free cells and at least
/// `min_distance` world units apart, or `None` after 1000 draws. For queries on maps
/// that come without one.
pub fn random_query<R: Rng + ?Sized>(
    map: &GridMap,
    min_distance: f64,
    rng: &mut R,
) -> Option<(Point2, Point2)> {
    let (w, h) = (map.width(), map.height());
    let draw = |rng: &mut R| {
        (0..1000).find_map(|_| {
            let (i, j) = (rng.random_range(0..w), rng.random_range(0..h));
            map.cell_free(i, j).then_some((i, j))
        })
    };
    let canvas = Canvas {
        width: w,
        height: h,
        blocked: (0..h)
            .flat_map(|j| (0..w).map(move |i| (i, j)))
            .map(|(i, j)| !map.cell_free(i, j))
            .collect(),
    };
    for _ in 0..1000 {
        let (a, b) = (draw(rng)?, draw(rng)?);
        let (pa, pb) = (map.cell_center(a.0, a.1), map.cell_center(b.0, b.1));
        if (pa - pb).norm() >= min_distance && connected(&canvas, a, b) {
            return Some((pa, pb));
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use hyplan_core::Workspace;
    use rand::SeedableRng;

    /// Whether the map's non-Forbidden cells join start and goal.
    fn joined(g: &Generated) -> bool {
        let canvas = Canvas {
            width: g.map.width(),
            height: g.map.height(),
            blocked: g
                .map
                .zones()
                .iter()
                .map(|&z| z == Zone::Forbidden)
                .collect(),
        };
        let cell = |p: Point2| g.map.world_to_cell(p).unwrap();
        connected(&canvas, cell(g.start), cell(g.goal))
    }

    fn check(g: &Generated) {
        assert!(g.map.is_free(g.start), "start blocked");
        assert!(g.map.is_free(g.goal), "goal blocked");
        assert!(joined(g));
    }

    #[test]
    fn every_kind_is_connected_and_deterministic() {
        for kind in HardMap::ALL {
            for seed in 0..3 {
                let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
                let step = if kind == HardMap::FloorPlan {
                    40.0
                } else {
                    4.0
                };
                let g = kind.generate(step, &mut rng);
                check(&g);
                let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
                assert_eq!(g, kind.generate(step, &mut rng), "{}", kind.name());
            }
        }
    }

    #[test]
    fn floor_plan_is_large_and_has_rooms() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
        let g = floor_plan(2000, 2000, 60, 4, &mut rng);
        assert_eq!((g.map.width(), g.map.height()), (2000, 2000));
        let [free, _, forbidden] = g.map.zone_counts();
        assert!(forbidden > 40_000 && free > 3_000_000, "{forbidden} {free}");
    }

    #[test]
    fn gap_zero_disconnects() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
        let g = narrow_passage(40, 20, 0, 3, &mut rng);
        assert_eq!((g.map.width(), g.map.height()), (40, 20));
        assert!(!joined(&g));
    }

    #[test]
    fn risk_band_marks_cells_near_walls() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
        let g = narrow_passage(40, 20, 4, 3, &mut rng);
        let banded = with_risk_band(&g.map, 2.0);
        assert!(banded.zone_counts()[1] > 0);
        assert_eq!(banded.zone_counts()[2], g.map.zone_counts()[2]);
    }
}
