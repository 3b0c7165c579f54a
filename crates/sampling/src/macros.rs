//! The [`Planner`](hyplan_core::Planner) implementation every tree planner writes the same
//! way, written once.

/// Implements [`Planner`](hyplan_core::Planner) for a planner type from its inherent,
/// generic `plan(&self, ws, query, rng)`: [`info`](hyplan_core::Planner::info) gives the
/// name and capabilities (no planner built on a tree proves "no path" by exhausting it),
/// [`plan`](hyplan_core::Planner::plan) forwards the `dyn` workspace and RNG.
///
/// - `impl_planner!(Type, "name", optimizing: |planner| expr)`: any workspace; `expr`
///   (with `planner` bound to `&self`) says whether more budget improves the path.
/// - `impl_planner!(Type, "name", optimizing: |planner| expr, plan: plan_with)` also writes
///   the inherent `plan`: `plan_with(ws, query, rng, observer)` with an observer that never
///   stops the run.
/// - `impl_planner!(Type, "name", optimizing: |planner| expr, plan: search)` also writes
///   the inherent, generic `plan_with(ws, query, rng, observer)`, which hands them as a
///   [`Search`](crate::Search) to the planner's own `search(&self, Search<'_, W>)`, and
///   `plan` as above.
/// - `impl_planner!(Type, "name", optimizing: |planner| expr, plan: plan_detailed)` also
///   writes the inherent `plan`: the plan of `plan_detailed(ws, query, rng)` (a
///   `Result<T, PlanError>` where `T` has a `plan` field).
/// - `impl_planner!(Type, "name", optimizing: |planner| expr, staged: Staged)` also writes
///   the inherent, generic `plan_detailed(ws, query, rng)`, which hands them as a
///   [`Search`](crate::Search) (with an observer that never stops the run) to the
///   planner's own `staged(&self, Search<'_, W>) -> Result<Staged, PlanError>`, and
///   `plan` from it as above.
/// - `impl_planner!(Type, "name", grid_only, staged: Staged)`: as the last, on an
///   `envmap::GridMap` only (`staged(&self, Search<'_, GridMap>)`), with the `grid_only`
///   implementation of the next form.
/// - `impl_planner!(Type, "name", grid_only, plan: plan_detailed)`: as the `plan_detailed`
///   form above, for a planner whose `plan_detailed` takes an `envmap::GridMap`; the `dyn`
///   workspace is found with `GridMap::of_workspace` (an error naming the planner for any
///   other workspace), so the calling crate depends on `envmap`.
///
/// ```
/// use hyplan_core::{Plan, PlanError, PlanStats, Planner, Query, Workspace};
/// use rand::SeedableRng;
///
/// /// Goes straight to the goal when it can.
/// struct Straight;
///
/// impl Straight {
///     fn plan<W: Workspace + ?Sized, R: rand::Rng + ?Sized>(
///         &self,
///         ws: &W,
///         query: &Query,
///         _rng: &mut R,
///     ) -> Result<Plan, PlanError> {
///         let path = vec![query.start, query.goal.center()];
///         let stats = PlanStats::default();
///         if !ws.segment_free(path[0], path[1]) {
///             return Err(PlanError::BudgetExhausted { stats });
///         }
///         Ok(sampling::plan_of_path(path, Vec::new(), stats))
///     }
/// }
///
/// sampling::impl_planner!(Straight, "straight", optimizing: |_planner| false);
///
/// let planner: Box<dyn Planner> = Box::new(Straight);
/// assert_eq!(planner.info().name, "straight");
/// let map = envmap::GridMap::from_ascii("....")?;
/// let query = Query::new(
///     hyplan_core::Point2::new(0.5, 0.5),
///     hyplan_core::Goal::Point(hyplan_core::Point2::new(3.5, 0.5)),
/// );
/// let plan = planner.plan(&map, &query, &mut rand_chacha::ChaCha8Rng::seed_from_u64(0))?;
/// assert_eq!(plan.cost, 3.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[macro_export]
macro_rules! impl_planner {
    ($planner:ty, $name:literal, optimizing: |$this:ident| $optimizing:expr) => {
        $crate::impl_planner!(@impl $planner, $name, |$this| $optimizing, false, |ws| ws);
    };
    ($planner:ty, $name:literal, optimizing: |$this:ident| $optimizing:expr, plan: $entry:ident) => {
        $crate::impl_planner!($planner, $name, optimizing: |$this| $optimizing);
        $crate::impl_planner!(@$entry $planner);
    };
    ($planner:ty, $name:literal, grid_only, plan: plan_detailed) => {
        $crate::impl_planner!(
            @impl $planner, $name, |_planner| false, true,
            |ws| envmap::GridMap::of_workspace(ws, $name)?
        );
        impl $planner {
            /// Plans a path for `query` on `map`, drawing every random number from `rng`:
            /// [`plan_detailed`](Self::plan_detailed)'s plan.
            ///
            /// # Errors
            ///
            /// As [`plan_detailed`](Self::plan_detailed).
            pub fn plan<R: $crate::rand::Rng + ?Sized>(
                &self,
                map: &envmap::GridMap,
                query: &$crate::Query,
                rng: &mut R,
            ) -> ::std::result::Result<$crate::Plan, $crate::PlanError> {
                self.plan_detailed(map, query, rng).map(|staged| staged.plan)
            }
        }
    };
    ($planner:ty, $name:literal, optimizing: |$this:ident| $optimizing:expr, staged: $staged:ty) => {
        $crate::impl_planner!(@staged $planner, $staged, [W: $crate::Workspace + ?Sized,], W);
        $crate::impl_planner!($planner, $name, optimizing: |$this| $optimizing, plan: plan_detailed);
    };
    ($planner:ty, $name:literal, grid_only, staged: $staged:ty) => {
        $crate::impl_planner!(@staged $planner, $staged, [], envmap::GridMap);
        $crate::impl_planner!($planner, $name, grid_only, plan: plan_detailed);
    };
    (@staged $planner:ty, $staged:ty, [$($generic:tt)*], $ws:ty) => {
        impl $planner {
            /// Plans a path for `query` in `ws`, drawing every random number from `rng`,
            /// with the stages that led to it (the type's documentation says which).
            ///
            /// # Errors
            ///
            /// `PlanError::InvalidParameter` for a bad parameter or budget;
            /// `PlanError::InvalidStart` / `PlanError::InvalidGoal` for a query outside the
            /// workspace or blocked; any other error as the type's documentation says.
            pub fn plan_detailed<$($generic)* R: $crate::rand::Rng + ?Sized>(
                &self,
                ws: &$ws,
                query: &$crate::Query,
                rng: &mut R,
            ) -> ::std::result::Result<$staged, $crate::PlanError> {
                // `&mut R` is a sized RNG even when `R` is not: the same draws, in order.
                let mut rng = rng;
                self.staged($crate::Search {
                    ws,
                    query,
                    rng: &mut rng,
                    observer: &mut |_| ::std::ops::ControlFlow::Continue(()),
                })
            }
        }
    };
    (@search $planner:ty) => {
        impl $planner {
            /// Plans a path for `query` in `ws`, drawing every random number from `rng`, with
            /// `observer` called every [`OBSERVE_EVERY`](crate::OBSERVE_EVERY) iterations
            /// with the progress so far; `ControlFlow::Break(())` stops the run: the best
            /// path found so far for a planner that keeps improving one, else
            /// [`PlanError::BudgetExhausted`](crate::PlanError::BudgetExhausted).
            ///
            /// # Errors
            ///
            /// [`PlanError::InvalidParameter`](crate::PlanError::InvalidParameter) for a bad
            /// parameter or budget; [`PlanError::InvalidStart`](crate::PlanError::InvalidStart)
            /// / [`PlanError::InvalidGoal`](crate::PlanError::InvalidGoal) for a query outside
            /// the workspace or blocked;
            /// [`PlanError::Disconnected`](crate::PlanError::Disconnected) when the workspace
            /// proves start and goal apart;
            /// [`PlanError::BudgetExhausted`](crate::PlanError::BudgetExhausted) (with the
            /// statistics) when no path was found within the budget.
            pub fn plan_with<W, R, F>(
                &self,
                ws: &W,
                query: &$crate::Query,
                rng: &mut R,
                observer: &mut F,
            ) -> ::std::result::Result<$crate::Plan, $crate::PlanError>
            where
                W: $crate::Workspace + ?Sized,
                R: $crate::rand::Rng + ?Sized,
                F: FnMut(&$crate::Progress) -> ::std::ops::ControlFlow<()>,
            {
                // `&mut R` is a sized RNG even when `R` is not: the same draws, in order.
                let mut rng = rng;
                self.search($crate::Search {
                    ws,
                    query,
                    rng: &mut rng,
                    observer,
                })
            }
        }
        $crate::impl_planner!(@plan_with $planner);
    };
    (@plan_with $planner:ty) => {
        $crate::impl_planner!(
            @entry $planner, plan_with,
            |planner, ws, query, rng| planner.plan_with(ws, query, rng, &mut |_| {
                ::std::ops::ControlFlow::Continue(())
            })
        );
    };
    (@plan_detailed $planner:ty) => {
        $crate::impl_planner!(
            @entry $planner, plan_detailed,
            |planner, ws, query, rng| planner.plan_detailed(ws, query, rng).map(|s| s.plan)
        );
    };
    (@entry $planner:ty, $entry:ident, |$p:ident, $ws:ident, $q:ident, $r:ident| $call:expr) => {
        impl $planner {
            #[doc = concat!(
                "Plans a path for `query` in `ws`, drawing every random number from `rng`: [`",
                stringify!($entry), "`](Self::", stringify!($entry), ")'s plan.\n\n",
                "# Errors\n\nAs [`", stringify!($entry), "`](Self::", stringify!($entry), ")."
            )]
            pub fn plan<W: $crate::Workspace + ?Sized, R: $crate::rand::Rng + ?Sized>(
                &self,
                $ws: &W,
                $q: &$crate::Query,
                $r: &mut R,
            ) -> ::std::result::Result<$crate::Plan, $crate::PlanError> {
                let $p = self;
                $call
            }
        }
    };
    (@impl $planner:ty, $name:literal, |$this:ident| $optimizing:expr, $grid:literal,
        |$ws:ident| $view:expr) => {
        impl $crate::Planner for $planner {
            fn info(&self) -> $crate::PlannerInfo {
                let $this = self;
                $crate::PlannerInfo {
                    name: $name,
                    optimizing: $optimizing,
                    proves_no_path: false,
                    grid_only: $grid,
                }
            }

            fn plan(
                &self,
                $ws: &dyn $crate::Workspace,
                query: &$crate::Query,
                rng: &mut dyn $crate::rand::RngCore,
            ) -> ::std::result::Result<$crate::Plan, $crate::PlanError> {
                <$planner>::plan(self, $view, query, rng)
            }
        }
    };
}
