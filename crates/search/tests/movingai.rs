//! MovingAI optimality: every scenario of the repository's arena pair, and the peers' maze.

use std::path::Path;

use search::{GridOptions, GridSearch, ScenEntry, ScenError, parse_scen, read_scen};

use crate::common::{data_dir, legal_moves, load_movingai, octile_length, peer_maps_dir};

/// The data README's tolerance: the arena file prints about 6 significant digits.
fn tolerance(len: f64) -> f64 {
    f64::max(1e-3, 1e-5 * len)
}

fn check_all(map_path: &Path, scen_path: &Path, expected_count: usize) {
    let map = load_movingai(map_path);
    let scen = read_scen(scen_path).unwrap();
    assert_eq!(scen.len(), expected_count);
    let mut search = GridSearch::new(&map, GridOptions::default()).unwrap();
    for (id, s) in scen.iter().enumerate() {
        assert_eq!(
            s.map_file_name(),
            map_path.file_name().unwrap().to_str().unwrap()
        );
        let start = ScenEntry::to_cell(s.start, map.height()).unwrap();
        let goal = ScenEntry::to_cell(s.goal, map.height()).unwrap();
        let a = search.astar(start, goal).unwrap();
        let d = search.dijkstra(start, goal).unwrap();
        assert!(
            (a.cost - s.optimal).abs() <= tolerance(s.optimal),
            "scenario {id} (line {}): A* {} vs .scen {}",
            s.line,
            a.cost,
            s.optimal
        );
        assert!(
            (a.cost - d.cost).abs() < 1e-9,
            "scenario {id}: A* {} Dijkstra {}",
            a.cost,
            d.cost
        );
        assert!(legal_moves(&map, &a.cells), "scenario {id}: illegal move");
        assert!(legal_moves(&map, &d.cells), "scenario {id}: illegal move");
        assert!((octile_length(&a.cells) - a.cost).abs() < 1e-9);
        assert_eq!(a.cells.first(), Some(&start));
        assert_eq!(a.cells.last(), Some(&goal));
        // A* never expands more than Dijkstra.
        assert!(a.stats.expansions <= d.stats.expansions);
    }
}

#[test]
fn arena_all_160_scenarios_optimal() {
    let dir = data_dir().join("movingai");
    check_all(&dir.join("arena.map"), &dir.join("arena.map.scen"), 160);
}

#[test]
fn peers_maze_all_101_scenarios_optimal() {
    let dir = peer_maps_dir();
    check_all(&dir.join("maze.map"), &dir.join("maze.scen"), 101);
}

#[test]
fn peers_tiny_hand_computed() {
    let dir = peer_maps_dir();
    check_all(&dir.join("tiny.map"), &dir.join("tiny.scen"), 4);
}

#[test]
fn scen_errors_name_file_and_line() {
    let p = Path::new("bad.scen");
    let e = parse_scen("version 1\n0\tarena.map\t49\t49\t1\t11\t1\n", p).unwrap_err();
    assert!(
        matches!(
            e,
            ScenError::FieldCount {
                line: 2,
                found: 7,
                ..
            }
        ),
        "{e:?}"
    );
    assert_eq!(
        e.to_string(),
        "bad.scen:2: expected 9 tab-separated fields, found 7"
    );
    let e = parse_scen("version 1\n\n0\tarena.map\t49\t49\tx\t11\t1\t12\t1\n", p).unwrap_err();
    assert!(
        matches!(
            e,
            ScenError::Number {
                line: 3,
                field: "start x",
                ..
            }
        ),
        "{e:?}"
    );
    assert!(e.to_string().starts_with("bad.scen:3: field start x"));
    let e = parse_scen("version 1\n0\tarena.map\t49\t49\t1\t11\t1\t12\tNaN\n", p).unwrap_err();
    assert!(
        matches!(
            e,
            ScenError::Number {
                field: "optimal length",
                ..
            }
        ),
        "{e:?}"
    );
    let e = parse_scen("0\tarena.map\t49\t49\t1\t11\t1\t12\t1\n", p).unwrap_err();
    assert!(matches!(e, ScenError::Version { line: 1, .. }), "{e:?}");
    let e = read_scen("/nonexistent/x.scen").unwrap_err();
    assert!(e.to_string().contains("/nonexistent/x.scen"));
}

#[test]
fn scen_rows_count_from_the_top() {
    assert_eq!(ScenEntry::to_cell((3, 0), 10), Some((3, 9)));
    assert_eq!(ScenEntry::to_cell((3, 9), 10), Some((3, 0)));
    assert_eq!(ScenEntry::to_cell((3, 10), 10), None);
}
