//! The one growing tree of the RRT family: node ids, parent links, optional costs-to-come
//! and the nearest-neighbour index, with the operations RRT, RRT*, the two-tree planners,
//! the hybrids and the frontier detectors are made of.

use hyplan_core::{Goal, Plan, PlanError, PlanStats, Point2, Workspace};

use crate::NearestIndex;
use crate::kdtree::squared_distance;
use crate::toolkit::{self, CountingChecker};

/// A tree grown from a root: its nodes in a [`NearestIndex`] (ids are insertion order,
/// the root is node 0), a parent link per node and, for a tree made
/// [`with_costs`](Self::with_costs), a cost-to-come per node that
/// [`reparent`](Self::reparent) keeps right for a whole subtree (RRT*'s rewiring).
///
/// A plain tree ([`rooted_at`](Self::rooted_at)) stores no costs: RRT, the two-tree
/// planners and the frontier detectors need none, and pay nothing for them.
///
/// ```
/// use envmap::GridMap;
/// use hyplan_core::Point2;
/// use sampling::{CountingChecker, Extension, GrowTree};
///
/// let map = GridMap::from_ascii("
///     ......
///     ......
/// ")?;
/// let mut checker = CountingChecker::new(&map);
/// let mut tree = GrowTree::with_costs(Point2::new(0.5, 0.5));
/// // One RRT extension: nearest node, one step towards the target, exact edge check, add.
/// let Extension::Added { near, new } = tree.extend(Point2::new(5.5, 0.5), 2.0, &mut checker)
/// else { panic!("free map") };
/// assert_eq!((near, new), (0, 1));
/// assert_eq!(tree.point(new), Point2::new(2.5, 0.5));
/// assert_eq!(tree.cost(new), 2.0);
/// let b = tree.add(Point2::new(3.5, 0.5), new);
/// // Rewire: `new` gets a cheaper parent; its child `b` follows.
/// tree.reparent(new, 0, 1.5);
/// assert_eq!(tree.cost(b), 2.5);
/// assert_eq!(tree.branch(b), [Point2::new(0.5, 0.5), Point2::new(2.5, 0.5), Point2::new(3.5, 0.5)]);
/// assert_eq!(tree.to_tree().len(), 3);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct GrowTree<const B: usize = 64> {
    /// The nodes' points, in a k-d tree with leaves of `B` points (see [`NearestIndex`]).
    index: NearestIndex<B>,
    parent: Vec<Option<u32>>,
    /// Costs-to-come by id; empty in a plain tree.
    cost: Vec<f64>,
    /// Children by id, built at the first rewiring (only rewiring needs them); empty until
    /// then.
    children: Vec<Vec<u32>>,
    /// The goal followed by [`watch_goal`](Self::watch_goal), if any.
    goal: Option<GoalWatch>,
}

/// A goal's nearest node, followed as nodes are added ([`GrowTree::watch_goal`]).
#[derive(Debug, Clone, Copy)]
struct GoalWatch {
    at: Point2,
    /// The smallest squared distance from a node to `at`.
    best: f64,
    /// Two nodes at `best`: which one the index reports is then its own choice, so the
    /// watch stands aside.
    tied: bool,
    /// The last extension towards `at` was refused, and no node has come as near since.
    refused: bool,
}

impl GoalWatch {
    /// Takes in a node at `p`.
    #[inline]
    fn saw(&mut self, p: Point2) {
        let d2 = (p - self.at).norm_squared();
        if d2 < self.best {
            (self.best, self.tied, self.refused) = (d2, false, false);
        } else if d2 == self.best {
            self.tied = true;
        }
    }
}

/// A node nearer to a target than every other node of its tree, with its squared distance
/// to the target as the tree's index computes it ([`squared_distance`]): the next step
/// towards that target may start from it without a nearest query, which would report the
/// same node at the same distance (RRT-Connect's connect, [`GrowTree::step_led`]). Holds
/// until the tree gets another node.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Lead {
    target: Point2,
    node: usize,
    d2: f64,
}

/// What one [`GrowTree::extend`] did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Extension {
    /// A node `new` was added under `near`, the node nearest to the target.
    Added {
        /// The node extended.
        near: usize,
        /// The node added.
        new: usize,
    },
    /// The step was refused: it went nowhere (the target is a node) or its edge is blocked.
    Refused,
    /// The tree has no node a query can report (only non-finite points, or a non-finite
    /// target).
    NoNode,
}

/// One step of a tree towards a target: the node nearest to the target and the steered
/// point, not yet checked nor added (from [`GrowTree::step_towards`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Step {
    /// The node nearest to the target.
    pub near: usize,
    /// That node's point.
    pub from: Point2,
    /// At most one step from `from` towards the target ([`steer`](crate::steer)).
    pub to: Point2,
}

impl GrowTree {
    /// A plain tree (no costs) holding only `root`, node 0.
    #[must_use]
    pub fn rooted_at(root: Point2) -> Self {
        Self::rooted_in_buckets(root)
    }

    /// A tree with costs-to-come holding only `root`, node 0, at cost 0.
    #[must_use]
    pub fn with_costs(root: Point2) -> Self {
        Self {
            cost: vec![0.0],
            ..Self::rooted_at(root)
        }
    }
}

impl<const B: usize> GrowTree<B> {
    /// [`rooted_at`](GrowTree::rooted_at) with the nodes' k-d tree in leaves of `B`
    /// points ([`NearestIndex::with_bucket_capacity`]).
    ///
    /// ```
    /// use hyplan_core::Point2;
    /// use sampling::GrowTree;
    /// let mut tree = GrowTree::<256>::rooted_in_buckets(Point2::new(0.0, 0.0));
    /// tree.add(Point2::new(1.0, 0.0), 0);
    /// assert_eq!(tree.nearest(Point2::new(2.0, 0.0)), Some((1, 1.0)));
    /// ```
    #[must_use]
    pub fn rooted_in_buckets(root: Point2) -> Self {
        Self {
            index: NearestIndex::rooted_in_buckets(root),
            // As much room as the index's.
            parent: {
                let mut parent = Vec::with_capacity(B);
                parent.push(None);
                parent
            },
            cost: Vec::new(),
            children: Vec::new(),
            goal: None,
        }
    }

    /// Number of nodes.
    #[must_use]
    pub fn len(&self) -> usize {
        self.parent.len()
    }

    /// Never: the tree holds at least its root.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The point of node `id`.
    ///
    /// # Panics
    ///
    /// If `id` is not a node of the tree.
    #[must_use]
    pub fn point(&self, id: usize) -> Point2 {
        self.index.point(id)
    }

    /// Every node's point, in id order.
    #[must_use]
    pub fn points(&self) -> &[Point2] {
        self.index.points()
    }

    /// Every node's parent link (`None` for the root), in id order.
    #[must_use]
    pub fn parents(&self) -> &[Option<u32>] {
        &self.parent
    }

    /// The parent of node `id` (`None` for the root).
    ///
    /// # Panics
    ///
    /// If `id` is not a node of the tree.
    #[must_use]
    pub fn parent(&self, id: usize) -> Option<usize> {
        self.parent[id].map(|p| p as usize)
    }

    /// The cost-to-come of node `id`: as given to [`add_with_cost`](Self::add_with_cost) or
    /// [`reparent`](Self::reparent) (or the parent's plus the edge length for
    /// [`add`](Self::add)) in a tree with costs; the length of its branch in a plain tree
    /// (walked, so `O(depth)`).
    ///
    /// # Panics
    ///
    /// If `id` is not a node of the tree.
    #[must_use]
    pub fn cost(&self, id: usize) -> f64 {
        if self.cost.is_empty() {
            hyplan_core::path_length(&self.branch(id))
        } else {
            self.cost[id]
        }
    }

    /// The node nearest to `p` and its distance ([`NearestIndex::nearest`]).
    #[must_use]
    pub fn nearest(&self, p: Point2) -> Option<(usize, f64)> {
        self.index.nearest(p)
    }

    /// The `k` nodes nearest to `p`, nearest first ([`NearestIndex::nearest_k`]).
    #[must_use]
    pub fn nearest_k(&self, p: Point2, k: usize) -> Vec<(usize, f64)> {
        self.index.nearest_k(p, k)
    }

    /// The nodes within `radius` of `p` into `out` ([`NearestIndex::within_into`]).
    pub fn within_into(&self, p: Point2, radius: f64, out: &mut Vec<(usize, f64)>) {
        self.index.within_into(p, radius, out);
    }

    /// Adds `p` under `parent` and returns its id; in a tree with costs its cost is the
    /// parent's plus the edge length.
    ///
    /// # Panics
    ///
    /// If `parent` is not a node of the tree.
    pub fn add(&mut self, p: Point2, parent: usize) -> usize {
        self.attach(p, parent, self.cost_via(p, parent), false)
    }

    /// The cost-to-come of a node at `p` under `parent` (0 in a plain tree).
    #[inline]
    fn cost_via(&self, p: Point2, parent: usize) -> f64 {
        if self.cost.is_empty() {
            0.0
        } else {
            self.cost[parent] + (p - self.index.point(parent)).norm()
        }
    }

    /// Follows `goal`, a target that [`extend`](Self::extend) is handed again and again
    /// (RRT's goal-biased samples): an extension towards it that was refused is refused
    /// again at once, without the nearest query and the edge check, until a node as near
    /// to it as its nearest is added. Both would give what they gave before (the same
    /// nearest node, the same step, the same edge), so the tree grows exactly as without
    /// the watch; only fewer checks are counted. On a maze most goal samples are such
    /// repeats.
    ///
    /// ```
    /// use envmap::GridMap;
    /// use hyplan_core::Point2;
    /// use sampling::{CountingChecker, Extension, GrowTree};
    ///
    /// let map = GridMap::from_ascii("
    ///     ..#..
    ///     ..#..
    /// ")?;
    /// let goal = Point2::new(4.5, 0.5);
    /// let mut checker = CountingChecker::new(&map);
    /// let mut tree = GrowTree::rooted_at(Point2::new(0.5, 0.5));
    /// tree.watch_goal(goal);
    /// assert_eq!(tree.extend(goal, 4.0, &mut checker), Extension::Refused);
    /// assert_eq!(tree.extend(goal, 4.0, &mut checker), Extension::Refused);
    /// assert_eq!(checker.checks, 1);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn watch_goal(&mut self, goal: Point2) {
        let mut watch = GoalWatch {
            at: goal,
            best: f64::INFINITY,
            tied: false,
            refused: false,
        };
        for &p in self.index.points() {
            watch.saw(p);
        }
        self.goal = Some(watch);
    }

    /// Adds `p` under `parent` with cost-to-come `cost` (ignored by a plain tree) and
    /// returns its id.
    ///
    /// # Panics
    ///
    /// If `parent` is not a node of the tree.
    pub fn add_with_cost(&mut self, p: Point2, parent: usize, cost: f64) -> usize {
        self.attach(p, parent, cost, false)
    }

    /// [`add_with_cost`](Self::add_with_cost); `new` when `p` is known to equal no node
    /// ([`NearestIndex::insert_new`]).
    #[inline]
    fn attach(&mut self, p: Point2, parent: usize, cost: f64, new: bool) -> usize {
        assert!(parent < self.parent.len(), "parent {parent} is not a node");
        let id = if new {
            self.index.insert_new(p)
        } else {
            self.index.insert(p)
        };
        if let Some(watch) = &mut self.goal {
            watch.saw(p);
        }
        self.parent.push(Some(parent as u32));
        if !self.cost.is_empty() {
            self.cost.push(cost);
        }
        if !self.children.is_empty() {
            self.children.push(Vec::new());
            self.children[parent].push(id as u32);
        }
        id
    }

    /// Rewires: makes `new_parent` the parent of `node`, with cost `cost`, and shifts the
    /// costs of the whole subtree of `node` by the same amount (a plain tree only relinks).
    ///
    /// # Panics
    ///
    /// If `node` or `new_parent` is not a node of the tree.
    pub fn reparent(&mut self, node: usize, new_parent: usize, cost: f64) {
        assert!(new_parent < self.parent.len(), "{new_parent} is not a node");
        if self.cost.is_empty() {
            self.parent[node] = Some(new_parent as u32);
            return;
        }
        if self.children.is_empty() {
            // Built in id order, as `add` would have kept them.
            self.children = vec![Vec::new(); self.parent.len()];
            for (id, p) in self.parent.iter().enumerate() {
                if let Some(p) = p {
                    self.children[*p as usize].push(id as u32);
                }
            }
        }
        if let Some(old) = self.parent[node] {
            let siblings = &mut self.children[old as usize];
            if let Some(pos) = siblings.iter().position(|&c| c as usize == node) {
                siblings.swap_remove(pos);
            }
        }
        self.parent[node] = Some(new_parent as u32);
        self.children[new_parent].push(node as u32);
        let delta = cost - self.cost[node];
        self.cost[node] = cost;
        let mut stack: Vec<u32> = self.children[node].clone();
        while let Some(c) = stack.pop() {
            self.cost[c as usize] += delta;
            stack.extend_from_slice(&self.children[c as usize]);
        }
    }

    /// The node nearest to `target` and the point at most `step` from it towards the
    /// target; `None` when no node can be reported ([`NearestIndex::nearest`]).
    #[must_use]
    pub fn step_towards(&self, target: Point2, step: f64) -> Option<Step> {
        let (near, len) = self.index.nearest(target)?;
        let from = self.index.point(near);
        Some(Step {
            near,
            from,
            to: toolkit::steer_by(from, target, len, step),
        })
    }

    /// [`step_towards`](Self::step_towards), from `lead`'s node when it leads towards
    /// `target` (it must be this tree's, with no node added since [`add_step`](Self::add_step)
    /// made it).
    pub(crate) fn step_led(&self, target: Point2, step: f64, lead: Option<Lead>) -> Option<Step> {
        let Some(lead) = lead.filter(|l| l.target == target) else {
            return self.step_towards(target, step);
        };
        let from = self.index.point(lead.node);
        Some(Step {
            near: lead.node,
            from,
            to: toolkit::steer_by(from, target, lead.d2.sqrt(), step),
        })
    }

    /// Adds step `s` towards `target` (from [`step_led`](Self::step_led), its edge
    /// checked): its point under its node, as [`add`](Self::add). Returns the new node and,
    /// when it is nearer to `target` than the step's node, its [`Lead`].
    #[inline]
    pub(crate) fn add_step(&mut self, s: &Step, target: Point2) -> (usize, Option<Lead>) {
        let t = [target.x, target.y];
        let d2 = squared_distance([s.to.x, s.to.y], t);
        // The step's node is the nearest to the target: a node equal to the new point would
        // be nearer still.
        let new = d2 < squared_distance([s.from.x, s.from.y], t);
        let id = self.attach(s.to, s.near, self.cost_via(s.to, s.near), new);
        let lead = new.then_some(Lead {
            target,
            node: id,
            d2,
        });
        (id, lead)
    }

    /// RRT's extension: [`step_towards`](Self::step_towards) the target, then, unless the
    /// step goes nowhere, the counted exact edge check, then [`add`](Self::add). Towards a
    /// watched goal ([`watch_goal`](Self::watch_goal)) a repeat of a refused extension is
    /// refused without either.
    #[inline]
    pub fn extend<W: Workspace + ?Sized>(
        &mut self,
        target: Point2,
        step: f64,
        checker: &mut CountingChecker<'_, W>,
    ) -> Extension {
        let watched = self.goal.filter(|w| w.at == target);
        if watched.is_some_and(|w| w.refused && !w.tied) {
            return Extension::Refused;
        }
        let Some(s) = self.step_towards(target, step) else {
            return Extension::NoNode;
        };
        if s.to == s.from || !checker.segment_free(s.from, s.to) {
            if let (Some(watch), Some(_)) = (&mut self.goal, watched) {
                watch.refused = true;
            }
            return Extension::Refused;
        }
        Extension::Added {
            near: s.near,
            new: self.add_step(&s, target).0,
        }
    }

    /// RRT's join of an exact goal: when the goal is a point (or a disc of radius 0)
    /// within `step` of node `node` (and not on it) and the edge to it is free, adds the
    /// goal under `node` and returns its id.
    #[inline]
    pub fn join_goal<W: Workspace + ?Sized>(
        &mut self,
        node: usize,
        goal: &Goal,
        step: f64,
        checker: &mut CountingChecker<'_, W>,
    ) -> Option<usize> {
        if goal.radius() > 0.0 {
            return None;
        }
        let (p, g) = (self.point(node), goal.center());
        // The distance inline (RRT asks at every new node, and most are far from the goal);
        // the edge check and the join apart.
        if (g - p).norm_squared() <= step * step && g != p {
            self.join_point((node, p), g, checker)
        } else {
            None
        }
    }

    /// [`join_goal`](Self::join_goal)'s edge check and join.
    #[inline(never)]
    fn join_point<W: Workspace + ?Sized>(
        &mut self,
        (node, p): (usize, Point2),
        g: Point2,
        checker: &mut CountingChecker<'_, W>,
    ) -> Option<usize> {
        checker.segment_free(p, g).then(|| self.add(g, node))
    }

    /// RRT*'s choose-parent for a new point `p`: the cheapest cost-to-come among the
    /// neighbours `near` (`(id, distance)`) through a free edge, where going through a
    /// neighbour at `q` costs its cost plus `edge(q, distance)`. `nearest` is the node the
    /// point was steered from with its cost through it; its edge is known to be free, so
    /// only cheaper candidates are checked, in cost order (ties: lower id). `scratch` is a
    /// buffer reused between calls. Returns the parent and the new point's cost.
    pub fn choose_parent<W: Workspace + ?Sized>(
        &self,
        p: Point2,
        nearest: (usize, f64),
        near: &[(usize, f64)],
        edge: impl Fn(Point2, f64) -> f64,
        checker: &mut CountingChecker<'_, W>,
        scratch: &mut Vec<(f64, usize)>,
    ) -> (usize, f64) {
        scratch.clear();
        scratch.extend(
            near.iter()
                .filter(|&&(i, _)| i != nearest.0)
                .map(|&(i, d)| (self.cost[i] + edge(self.point(i), d), i))
                .filter(|&(c, _)| c < nearest.1),
        );
        scratch.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        scratch
            .iter()
            .find(|&&(_, i)| checker.segment_free(self.point(i), p))
            .map_or(nearest, |&(c, i)| (i, c))
    }

    /// RRT*'s rewiring around the new node `new`: each neighbour in `near` (`(id,
    /// distance)`, its parent excepted) that becomes cheaper through it, by `new`'s cost
    /// plus `edge(neighbour point, distance)`, over a free edge, changes parent.
    pub fn rewire<W: Workspace + ?Sized>(
        &mut self,
        new: usize,
        near: &[(usize, f64)],
        edge: impl Fn(Point2, f64) -> f64,
        checker: &mut CountingChecker<'_, W>,
    ) {
        let (p, parent, cost) = (self.point(new), self.parent(new), self.cost[new]);
        for &(i, d) in near {
            if Some(i) == parent {
                continue;
            }
            let q = self.point(i);
            let through = cost + edge(q, d);
            if through < self.cost[i] && checker.segment_free(p, q) {
                self.reparent(i, new, through);
            }
        }
    }

    /// The branch from the root down to `leaf`, in path order ([`branch`](crate::branch)).
    ///
    /// # Panics
    ///
    /// If `leaf` is not a node of the tree.
    #[must_use]
    pub fn branch(&self, leaf: usize) -> Vec<Point2> {
        toolkit::branch(self.index.points(), &self.parent, leaf)
    }

    /// The points from node `leaf` up to the root, `leaf`'s first.
    pub(crate) fn climb(&self, leaf: usize) -> impl Iterator<Item = Point2> + '_ {
        toolkit::climb(self.index.points(), &self.parent, leaf)
    }

    /// Every edge as (parent point, child point), in child id order.
    pub fn edges(&self) -> impl Iterator<Item = (Point2, Point2)> + '_ {
        let points = self.index.points();
        self.parent
            .iter()
            .zip(points)
            .filter_map(|(p, &q)| p.map(|p| (points[p as usize], q)))
    }

    /// Plain-data copy for [`Plan::trees`].
    #[must_use]
    pub fn to_tree(&self) -> hyplan_core::Tree {
        hyplan_core::Tree {
            points: self.index.points().to_vec(),
            parent: self.parent.clone(),
        }
    }

    /// [`to_tree`](Self::to_tree) without a copy.
    #[must_use]
    pub fn into_tree(self) -> hyplan_core::Tree {
        hyplan_core::Tree {
            points: self.index.into_points(),
            parent: self.parent,
        }
    }

    /// The end of a one-tree run: the branch from the root to `leaf` as the plan (cost: its
    /// length), with the tree and `stats`.
    ///
    /// # Errors
    ///
    /// Without a leaf, [`PlanError::BudgetExhausted`] with `stats`.
    pub fn into_plan(self, leaf: Option<usize>, stats: PlanStats) -> Result<Plan, PlanError> {
        let Some(leaf) = leaf else {
            return Err(PlanError::BudgetExhausted { stats });
        };
        let path = self.branch(leaf);
        Ok(toolkit::plan_of_path(path, vec![self.into_tree()], stats))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point2 {
        Point2::new(x, y)
    }

    proptest::proptest! {
        /// A tree watching its goal grows exactly as one that does not, on any map and
        /// any mix of goal and other targets, with no more edge checks.
        #[test]
        fn a_watched_goal_changes_no_extension(
            cells in proptest::collection::vec(proptest::bool::weighted(0.25), 100),
            goal in (0.0..10.0_f64, 0.0..10.0_f64),
            targets in proptest::collection::vec(proptest::option::weighted(0.7, (0.0..10.0_f64, 0.0..10.0_f64)), 1..300),
            step in 0.3..4.0_f64,
        ) {
            let text: String = cells
                .chunks(10)
                .map(|row| row.iter().map(|&b| if b { '#' } else { '.' }).collect::<String>() + "\n")
                .collect();
            let map = envmap::GridMap::from_ascii(&text).unwrap();
            let goal = p(goal.0, goal.1);
            let (mut plain, mut watched) = (GrowTree::rooted_at(p(0.5, 0.5)), GrowTree::rooted_at(p(0.5, 0.5)));
            watched.watch_goal(goal);
            let (mut a, mut b) = (CountingChecker::new(&map), CountingChecker::new(&map));
            for target in targets {
                let target = target.map_or(goal, |(x, y)| p(x, y));
                let (x, y) = (plain.extend(target, step, &mut a), watched.extend(target, step, &mut b));
                proptest::prop_assert_eq!(x, y);
            }
            proptest::prop_assert_eq!(plain.points(), watched.points());
            proptest::prop_assert_eq!(plain.parents(), watched.parents());
            proptest::prop_assert!(b.checks <= a.checks);
        }

        /// Steps towards a target from the last step's lead are the steps a nearest query
        /// gives, and the points they add (without the search for an equal point) are the
        /// points plain adds give: on trees of small leaves with repeated points (half
        /// steps on a coarse lattice) and equidistant nodes.
        #[test]
        fn a_lead_steps_as_the_nearest_query(
            nodes in proptest::collection::vec((0..40_u8, 0..40_u8), 1..200),
            chases in proptest::collection::vec(((0..40_u8, 0..40_u8), 1..30_usize), 1..20),
            step in proptest::sample::select(vec![0.5, 1.0, 1.5, 2.0, 3.7]),
        ) {
            let at = |(x, y): (u8, u8)| p(f64::from(x) / 2.0, f64::from(y) / 2.0);
            let mut led = GrowTree::<8>::rooted_in_buckets(p(0.0, 0.0));
            for (k, &n) in nodes.iter().enumerate() {
                led.add(at(n), k / 2);
            }
            let mut plain = led.clone();
            for (target, steps) in chases {
                let target = at(target);
                let mut lead = None;
                for _ in 0..steps {
                    let s = led.step_led(target, step, lead).unwrap();
                    proptest::prop_assert_eq!(Some(s), plain.step_towards(target, step));
                    if s.from == target {
                        break;
                    }
                    lead = led.add_step(&s, target).1;
                    plain.add(s.to, s.near);
                }
            }
            proptest::prop_assert_eq!(led.points(), plain.points());
            proptest::prop_assert_eq!(led.nearest_k(p(7.3, 9.1), 50), plain.nearest_k(p(7.3, 9.1), 50));
        }
    }

    #[test]
    fn plain_tree_costs_are_branch_lengths_and_edges_follow_ids() {
        let mut tree = GrowTree::rooted_at(p(0.0, 0.0));
        let a = tree.add(p(3.0, 4.0), 0);
        let b = tree.add(p(3.0, 5.0), a);
        assert_eq!(tree.cost(b), 6.0);
        assert_eq!(tree.parent(b), Some(a));
        let edges: Vec<_> = tree.edges().collect();
        assert_eq!(
            edges,
            [(p(0.0, 0.0), p(3.0, 4.0)), (p(3.0, 4.0), p(3.0, 5.0))]
        );
        assert_eq!(tree.to_tree().edges().collect::<Vec<_>>(), edges);
    }

    #[test]
    fn rewiring_shifts_whole_subtrees_after_the_children_are_built() {
        let mut tree = GrowTree::with_costs(p(0.0, 0.0));
        // A chain 0 - 1 - 2 - 3 and a second child of 1.
        let n1 = tree.add(p(1.0, 1.0), 0);
        let n2 = tree.add(p(2.0, 1.0), n1);
        let n3 = tree.add(p(3.0, 1.0), n2);
        let n4 = tree.add(p(1.0, 2.0), n1);
        tree.reparent(n2, 0, 2.0);
        let before = tree.cost(n3);
        assert!((before - 3.0).abs() < 1e-12, "{before}");
        // Children kept up to date after the first rewiring.
        let n5 = tree.add(p(4.0, 1.0), n3);
        tree.reparent(n1, 0, 1.0);
        assert!((tree.cost(n4) - 2.0).abs() < 1e-12);
        assert!((tree.cost(n5) - 4.0).abs() < 1e-12);
        assert_eq!(tree.branch(n5)[1], p(2.0, 1.0));
    }
}
