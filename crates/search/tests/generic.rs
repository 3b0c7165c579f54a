//! The generic closures-based searches.

use search::{BacktrackLimits, NotFound, astar, backtrack, dijkstra};

/// A 4-connected grid given as closures: `#` blocked, rows top first.
struct Maze {
    rows: Vec<Vec<u8>>,
}

impl Maze {
    fn new(text: &str) -> Self {
        Self {
            rows: text
                .lines()
                .map(str::trim)
                .filter(|l| !l.is_empty())
                .map(|l| l.bytes().collect())
                .collect(),
        }
    }
    fn free(&self, x: i32, y: i32) -> bool {
        y >= 0
            && x >= 0
            && (y as usize) < self.rows.len()
            && (x as usize) < self.rows[0].len()
            && self.rows[y as usize][x as usize] != b'#'
    }
    fn succ(&self, (x, y): (i32, i32)) -> Vec<((i32, i32), f64)> {
        [(1, 0), (-1, 0), (0, 1), (0, -1)]
            .into_iter()
            .map(|(dx, dy)| (x + dx, y + dy))
            .filter(|&(x, y)| self.free(x, y))
            .map(|p| (p, 1.0))
            .collect()
    }
}

const MAZE: &str = "
    ..........
    .########.
    .#......#.
    .#.####.#.
    .#.#..#.#.
    ...#..#...
";

#[test]
fn astar_and_dijkstra_agree_on_a_maze() {
    let m = Maze::new(MAZE);
    let goal = (4, 4);
    let h = |&(x, y): &(i32, i32)| f64::from((x - goal.0).abs() + (y - goal.1).abs());
    // (4, 4) is walled in on three sides and reached only from (5, 4)/(4, 5)... which are
    // themselves enclosed: the pocket is unreachable.
    let a = astar(&(0, 0), |&p| m.succ(p), h, |&p| p == goal);
    assert!(matches!(a, Err(NotFound::Exhausted { .. })), "{a:?}");
    let reachable_goal = (2, 5);
    let a = astar(&(0, 0), |&p| m.succ(p), |_| 0.0, |&p| p == reachable_goal).unwrap();
    let d = dijkstra(&(0, 0), |&p| m.succ(p), |&p| p == reachable_goal).unwrap();
    assert_eq!(a.cost, d.cost);
    assert_eq!(a.cost, 7.0); // down 5 to (0,5), right 2 to (2,5)
    assert_eq!(a.path.len(), 8);
    assert_eq!(a.path.first(), Some(&(0, 0)));
    assert_eq!(a.path.last(), Some(&reachable_goal));
}

#[test]
fn exhausted_counts_every_reachable_node() {
    // A 3-node line with no goal: the search must expand all 3 before giving up.
    let r = dijkstra(
        &0u8,
        |&n| if n < 2 { vec![(n + 1, 1.0)] } else { vec![] },
        |_| false,
    );
    let stats = r.unwrap_err().stats();
    assert_eq!((stats.expansions, stats.reached, stats.pushes), (3, 3, 3));
}

#[test]
fn fractional_costs_pick_the_cheaper_route() {
    // 0 -> 1 -> 3 costs 0.1 + 0.1; 0 -> 3 costs 0.3.
    let succ = |&n: &u8| match n {
        0 => vec![(1, 0.1), (3, 0.3)],
        1 => vec![(3, 0.1)],
        _ => vec![],
    };
    let r = astar(&0u8, succ, |_| 0.0, |&n| n == 3).unwrap();
    assert_eq!(r.path, vec![0, 1, 3]);
    assert!((r.cost - 0.2).abs() < 1e-15);
}

#[test]
fn start_is_goal() {
    let r = astar(&7u8, |_| Vec::<(u8, f64)>::new(), |_| 0.0, |&n| n == 7).unwrap();
    assert_eq!(r.path, vec![7]);
    assert_eq!(r.cost, 0.0);
    let r = backtrack(
        &7u8,
        |_| Vec::<(u8, f64)>::new(),
        |_| 0.0,
        |&n| n == 7,
        BacktrackLimits::default(),
    )
    .unwrap();
    assert_eq!(r.path, vec![7]);
}

#[test]
fn backtrack_finds_a_simple_legal_path_and_undoes_dead_ends() {
    let m = Maze::new(MAZE);
    let goal = (9, 5);
    let h = |&(x, y): &(i32, i32)| f64::from((x - goal.0).abs() + (y - goal.1).abs());
    let r = backtrack(
        &(2, 5),
        |&p| m.succ(p),
        h,
        |&p| p == goal,
        BacktrackLimits::default(),
    )
    .unwrap();
    assert_eq!(r.path.first(), Some(&(2, 5)));
    assert_eq!(r.path.last(), Some(&goal));
    // Every step is an edge of the graph.
    for w in r.path.windows(2) {
        assert!(m.succ(w[0]).iter().any(|(n, _)| *n == w[1]), "{w:?}");
    }
    // Simple path.
    let mut seen = std::collections::HashSet::new();
    assert!(r.path.iter().all(|p| seen.insert(*p)));
    assert_eq!(r.cost, (r.path.len() - 1) as f64);
    // Not optimal in general, but never shorter than A*.
    let a = astar(&(2, 5), |&p| m.succ(p), h, |&p| p == goal).unwrap();
    assert!(r.cost >= a.cost);
}

#[test]
fn backtrack_proves_unreachable_and_respects_budgets() {
    let m = Maze::new(MAZE);
    let r = backtrack(
        &(0, 0),
        |&p| m.succ(p),
        |_| 0.0,
        |&p| p == (4, 4),
        BacktrackLimits::default(),
    );
    assert!(matches!(r, Err(NotFound::Exhausted { .. })), "{r:?}");
    let limits = BacktrackLimits {
        max_depth: usize::MAX,
        max_expansions: 3,
    };
    let r = backtrack(&(0, 0), |&p| m.succ(p), |_| 0.0, |&p| p == (9, 5), limits);
    assert!(matches!(r, Err(NotFound::BudgetExhausted { .. })), "{r:?}");
    // The goal is 14 steps away along the shortest route: a depth cap of 5 cannot reach it
    // and the failure is not claimed as a proof.
    let limits = BacktrackLimits {
        max_depth: 5,
        max_expansions: 1_000_000,
    };
    let r = backtrack(&(0, 0), |&p| m.succ(p), |_| 0.0, |&p| p == (9, 5), limits);
    assert!(matches!(r, Err(NotFound::BudgetExhausted { .. })), "{r:?}");
}

#[test]
fn backtrack_tries_the_best_child_first() {
    // From 0: children 1 (h = 5) and 2 (h = 0), both leading to the goal 3.
    let succ = |&n: &u8| match n {
        0 => vec![(1, 1.0), (2, 1.0)],
        1 | 2 => vec![(3, 1.0)],
        _ => vec![],
    };
    let h = |&n: &u8| if n == 1 { 5.0 } else { 0.0 };
    let r = backtrack(&0u8, succ, h, |&n| n == 3, BacktrackLimits::default()).unwrap();
    assert_eq!(r.path, vec![0, 2, 3]);
    assert_eq!(r.stats.expansions, 2);
}
