//! Rolling and spinning resistance: a torque against the relative rotation of two touching
//! bodies, M_r = μ_r R F_n against rolling and M_s = μ_spin a F_n against spinning (3D), each
//! governed by a friction law of the pair's materials (see
//! [`stickslip_core::FrictionMaterial::with_rolling`]).
//!
//! **Mechanism.** avian's joint motors exist only on revolute and prismatic joints, and a
//! contact's rows cannot take a torque. So stickslip adds its own rows to avian's substep
//! solver: per resisting pair up to three angular rows (3D: two rolling axes of the contact
//! plane and the normal; 2D: the one rotation axis), each driving its component of the
//! bodies' relative angular velocity to the law's target (zero unless the law creeps) with
//! an impulse within the law's torque cap times the substep. They are warm-started with the
//! last substep's impulse and solved after avian's contact rows in both of its passes (with
//! bias and relax), on the same solver bodies, so the resisting torque, the contact's
//! friction and its normal force come out of one solve: a ball held on a slope is held by
//! the friction that stops it sliding and the torque that stops it rolling together.
//!
//! **The law.** Once per tick, in `apply`, each pair's rolling and spinning states are
//! stepped by the engine-free kernel (`stickslip_core::rolling`), exactly as a contact's
//! friction is: the "slip" is the arm times the relative angular velocity, the "measured
//! friction" the rows' impulses of the last tick over arm times normal impulse. While the law
//! sticks a row is rigid up to the law's capacity and nothing creeps; beyond it the law
//! yields and the row brakes at the law's sliding level μ(R|ω|).
//!
//! **Arms and freedom** as in stickslip-rapier: R is the reduced distance of the bodies'
//! centres of mass from the contact plane (a static or kinematic body counts as infinitely
//! large), a the
//! spread of the contact's points (R for a single point); a line of points rolls only about
//! the line, a patch not at all (its normal rows hold every turn).
//!
//! **Normal force.** The contact's last tick's (its normal impulses over the tick), as its
//! friction limit's: the torque cap lags the load by one tick.

use crate::dim::{Angular, lift};
use avian::dynamics::solver::solver_body::{SolverBody, SolverBodyInertia};
use avian::math::Vector;
use avian::prelude::*;
use bevy::platform::collections::HashMap;
use bevy::prelude::*;
use stickslip_bevy::{RollingReport, StickSlipRolling};
use stickslip_core::contact::{ContactState, World};
use stickslip_core::law::{FrictionLaw, Law};
use stickslip_core::rolling::{AxisStep, Freedom, freedom, reduced_arm, step_axis};
#[cfg(not(dim2))]
use stickslip_core::rolling::{RollingInput, step_rolling};

/// The rolling and spinning laws of a pair (its materials' own, or two sides' combined).
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct RotationLaws {
    pub rolling: Option<Law>,
    pub spinning: Option<Law>,
}

/// A body of a resisting pair, as `apply` sees it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RollingBody {
    pub entity: Option<Entity>,
    /// Whether it is dynamic: a static or kinematic body's arm is infinite (it is the ground
    /// the other rolls on, as its contacts treat it).
    pub dynamic: bool,
    pub angular: Angular,
    /// The largest inverse principal inertia, bounded from above (0 unless dynamic).
    pub inv_inertia: f32,
    /// The mean of the contact's anchors on it (from its centre of mass, world).
    pub anchor: Vector,
}

/// The contact of a resisting pair this tick: the manifold carrying the most points.
pub(crate) struct RollingContact<'a> {
    pub points: &'a [ContactPoint],
    pub normal: Vector,
    /// The contact's normal force of its last solve (N).
    pub normal_force: f64,
}

/// One resisting pair.
#[derive(Debug, Clone)]
struct Resisting {
    roll: ContactState,
    spin: ContactState,
    /// The world axes the rows acted along in the last tick (x: first rolling axis; 2D: z).
    axis_x: World,
    normal: World,
    arm_roll: f32,
    arm_spin: f32,
    /// The tick it was last stepped in.
    seen: u64,
    point: Vec3,
    normal_force: f64,
    resists: [bool; 2],
    /// The rows' angular impulse on body 2 over the last tick (rolling, spinning; world), for
    /// the read-back.
    impulse: [World; 2],
    /// The rows' impulse on body 2 in the last tick's last substep (rolling, spinning;
    /// world): the solve as it ended, for the law (as a contact's measurement, see
    /// `measure`), and the next tick's warm start.
    last: [World; 2],
    /// The last tick's substeps.
    substeps: u32,
}

/// One angular row of avian's substep solver.
#[derive(Debug, Clone, Copy)]
struct Row {
    pair: (Entity, Entity),
    bodies: [Option<Entity>; 2],
    axis: Angular,
    /// 0 rolling, 1 spinning.
    kind: usize,
    /// The impulse cap per substep (N·m·s).
    max: f32,
    target: f32,
    /// This substep's accumulated impulse on body 2 along the axis (warm-started).
    lambda: f32,
    /// Σ over the tick's substeps.
    total: f32,
}

/// Every resisting pair's states and this tick's rows (a resource).
#[derive(Resource, Default)]
pub(crate) struct Rolling {
    pairs: HashMap<(Entity, Entity), Resisting>,
    rows: Vec<Row>,
    tick: u64,
    dt: f64,
    /// The last tick's length (s): the rows' impulses were over it.
    last_dt: f64,
}

impl Rolling {
    /// Starts a tick of length `dt` (s): the last tick's rows were folded into their pairs
    /// after its solve (see `collect`).
    pub(crate) fn begin(&mut self, dt: f64) {
        self.tick += 1;
        self.last_dt = if self.dt > 0.0 { self.dt } else { dt };
        self.dt = dt;
        self.rows.clear();
    }

    /// Drops the pairs not stepped this tick (separated, asleep, despawned).
    pub(crate) fn end(&mut self) {
        let tick = self.tick;
        self.pairs.retain(|_, r| r.seen == tick);
    }

    /// Steps the pair `(c1, c2)`'s laws and adds its rows for this tick's substeps.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn step_pair(
        &mut self,
        pair: (Entity, Entity),
        laws: &RotationLaws,
        contact: RollingContact,
        (b1, b2): (RollingBody, RollingBody),
        substeps: u32,
        time: f64,
        stiffness_time: f64,
    ) {
        let dt = self.dt;
        let tick = self.tick;
        if b1.entity == b2.entity || contact.points.is_empty() {
            return;
        }
        let n = contact.normal;
        let arm = |b: RollingBody| {
            if b.dynamic {
                b.anchor.dot(n).abs()
            } else {
                f32::INFINITY
            }
        };
        let arm_roll = reduced_arm(arm(b1), arm(b2));
        if !(arm_roll.is_finite() && arm_roll > 0.0) {
            return;
        }
        let count = contact.points.len() as f32;
        let p = contact.points.iter().map(|q| q.point).sum::<Vector>() / count;
        let offsets = || {
            contact.points.iter().map(move |q| {
                let d = q.point - p;
                lift(d - n * n.dot(d)).to_array()
            })
        };
        let lever = laws
            .rolling
            .as_ref()
            .map_or(0.0, |l| l.static_coefficient() as f32 * arm_roll);
        let (freedom, spread) = freedom(offsets, lift(n).to_array(), lever, cfg!(not(dim2)));
        let arm_spin = if cfg!(not(dim2)) && spread > 1e-3 * arm_roll {
            spread
        } else {
            arm_roll
        };
        let f_n = contact.normal_force;
        let s = AxisStep {
            normal_force: f_n,
            dt,
            time,
            stiffness_time,
            inv_inertia: (b1.inv_inertia + b2.inv_inertia) as f64,
        };
        let r = self.pairs.entry(pair).or_insert_with(|| Resisting {
            roll: ContactState::default(),
            spin: ContactState::default(),
            axis_x: [0.0; 3],
            normal: [0.0; 3],
            arm_roll,
            arm_spin,
            seen: tick,
            point: Vec3::ZERO,
            normal_force: 0.0,
            resists: [false; 2],
            impulse: [[0.0; 3]; 2],
            last: [[0.0; 3]; 2],
            substeps: 1,
        });
        // The last solve's resisting "friction": its last substep's impulse on body 1 (the
        // opposite of body 2's) over arm times the normal impulse its caps were set from (a
        // cap the solve reached reads as the law's limit, whatever the load did since).
        let normal_impulse = r.normal_force * self.last_dt / r.substeps.max(1) as f64;
        let mu_of = |j: World, arm: f32| -> World {
            let lever = arm as f64 * normal_impulse;
            if lever > 0.0 {
                j.map(|x| (-(x as f64) / lever) as f32)
            } else {
                [0.0; 3]
            }
        };
        let w = b2.angular - b1.angular;
        let h = (dt / substeps.max(1) as f64) as f32;
        let mut rows: [Option<(Angular, usize, f64, f64)>; 3] = [None; 3];
        #[cfg(not(dim2))]
        let axis_x = {
            let n3 = n.to_array();
            let command = step_rolling(
                &mut r.roll,
                laws.rolling.as_ref(),
                &RollingInput {
                    freedom,
                    relative_angular_velocity: w.to_array(),
                    normal: n3,
                    arm: arm_roll,
                    last_axis: r.axis_x,
                    measured: mu_of(r.last[0], r.arm_roll),
                },
                s,
            );
            if laws.rolling.is_some() {
                let (x, z) = (Vec3::from(command.axis_x), Vec3::from(command.axis_z));
                rows[0] = Some((x, 0, command.caps[0], command.targets[0]));
                rows[1] = Some((z, 0, command.caps[1], command.targets[1]));
            }
            if let Some(law) = &laws.spinning {
                let measured = Vec3::from(mu_of(r.last[1], r.arm_spin)).dot(Vec3::from(r.normal));
                let (cap, target) =
                    step_axis(&mut r.spin, law, arm_spin, w.dot(n), measured as f64, s);
                rows[2] = Some((n, 1, cap, target));
            }
            command.axis_x
        };
        #[cfg(dim2)]
        let axis_x = {
            if freedom == Freedom::Blocked {
                // A patch does not roll: its normal rows hold the turn, with their lever.
                r.roll = ContactState::default();
            } else if let Some(law) = &laws.rolling {
                let measured = mu_of(r.last[0], r.arm_roll)[2];
                let (cap, target) = step_axis(&mut r.roll, law, arm_roll, w, measured as f64, s);
                rows[0] = Some((1.0, 0, cap, target));
            }
            [0.0, 0.0, 1.0]
        };
        for (axis, kind, cap, target) in rows.into_iter().flatten() {
            let max = (cap.max(0.0) * h as f64) as f32;
            if max.is_nan() || max <= 0.0 || !max.is_finite() || !target.is_finite() {
                continue;
            }
            let last = add(r.last[0], r.last[1]);
            let warm = dot_angular(last, axis).clamp(-max, max);
            let warm = if warm.is_finite() { warm } else { 0.0 };
            self.rows.push(Row {
                pair,
                bodies: [b1.entity, b2.entity],
                axis,
                kind,
                max,
                target: target as f32,
                lambda: warm,
                total: 0.0,
            });
        }
        r.axis_x = axis_x;
        r.normal = lift(n).to_array();
        r.arm_roll = arm_roll;
        r.arm_spin = arm_spin;
        r.seen = tick;
        r.point = lift(p);
        r.normal_force = f_n;
        r.resists = [
            laws.rolling.is_some() && freedom != Freedom::Blocked,
            cfg!(not(dim2)) && laws.spinning.is_some(),
        ];
        r.impulse = [[0.0; 3]; 2];
        r.last = [[0.0; 3]; 2];
        r.substeps = substeps.max(1);
    }
}

/// A world vector's component along an angular axis (2D: the z component, the axis ±1).
fn dot_angular(v: World, axis: Angular) -> f32 {
    #[cfg(not(dim2))]
    {
        Vec3::from(v).dot(axis)
    }
    #[cfg(dim2)]
    {
        v[2] * axis
    }
}

fn add(a: World, b: World) -> World {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// An angular impulse along `axis` as a world vector.
fn world_of(axis: Angular, lambda: f32) -> World {
    #[cfg(not(dim2))]
    {
        (axis * lambda).to_array()
    }
    #[cfg(dim2)]
    {
        [0.0, 0.0, axis * lambda]
    }
}

/// The solver bodies the rows act on.
type Bodies<'w, 's> = Query<'w, 's, (&'static mut SolverBody, &'static SolverBodyInertia)>;

/// The dominance of a static or sleeping body (no solver body), as avian's of a kinematic
/// one: above any dynamic body's.
const IMMOVABLE: i16 = i8::MAX as i16 + 1;

/// A body's angular velocity and world inverse inertia applied to `axis`, and its dominance
/// (a static or sleeping body has no solver body: at rest, immovable).
fn body(bodies: &Bodies, e: Option<Entity>, axis: Angular) -> (Angular, Angular, i16) {
    e.and_then(|e| bodies.get(e).ok()).map_or(
        (Angular::default(), Angular::default(), IMMOVABLE),
        |(b, i)| {
            (
                b.angular_velocity,
                i.effective_inv_angular_inertia() * axis,
                i.dominance(),
            )
        },
    )
}

/// The two bodies of a row: their angular velocities and inverse inertias applied to its
/// axis, the dominant one's (a kinematic body, or a higher `Dominance`) zero, as avian's
/// contacts treat them: a row does not push a kinematic platform or a dominant body.
fn pair_of(bodies: &Bodies, row: &Row) -> ((Angular, Angular), (Angular, Angular)) {
    let (w1, i1, d1) = body(bodies, row.bodies[0], row.axis);
    let (w2, i2, d2) = body(bodies, row.bodies[1], row.axis);
    let zero = Angular::default();
    let (i1, i2) = match d1.cmp(&d2) {
        std::cmp::Ordering::Greater => (zero, i2),
        std::cmp::Ordering::Less => (i1, zero),
        std::cmp::Ordering::Equal => (i1, i2),
    };
    ((w1, i1), (w2, i2))
}

/// One pass over the rows: each drives its axis' relative angular velocity to its target
/// within its cap. A non-finite impulse (from a body's non-finite velocity) starts over at
/// zero instead of staying in the rows and the warm start.
fn solve(rows: &mut [Row], bodies: &mut Bodies) {
    for row in rows.iter_mut() {
        let ((w1, i1), (w2, i2)) = pair_of(bodies, row);
        let k = dot(row.axis, i1) + dot(row.axis, i2);
        if k.is_nan() || k <= 0.0 {
            continue;
        }
        let v = dot(row.axis, w2 - w1) - row.target;
        let old = row.lambda;
        let lambda = (old - v / k).clamp(-row.max, row.max);
        row.lambda = if lambda.is_finite() { lambda } else { 0.0 };
        push(bodies, row.bodies, (i1, i2), row.lambda - old);
    }
}

/// Applies an impulse `d` along a row (i1, i2: the bodies' inverse inertia applied to its
/// axis): +d on body 2, −d on body 1.
fn push(bodies: &mut Bodies, [e1, e2]: [Option<Entity>; 2], (i1, i2): (Angular, Angular), d: f32) {
    if d == 0.0 || !d.is_finite() {
        return;
    }
    if let Some(Ok((mut b, _))) = e1.map(|e| bodies.get_mut(e)) {
        b.angular_velocity -= i1 * d;
    }
    if let Some(Ok((mut b, _))) = e2.map(|e| bodies.get_mut(e)) {
        b.angular_velocity += i2 * d;
    }
}

#[cfg(not(dim2))]
fn dot(a: Angular, b: Angular) -> f32 {
    a.dot(b)
}

#[cfg(dim2)]
fn dot(a: Angular, b: Angular) -> f32 {
    a * b
}

/// Substep: applies the rows' warm start (the last substep's impulses).
pub(crate) fn warm_start(mut rolling: ResMut<Rolling>, mut bodies: Bodies) {
    for row in rolling.rows.iter_mut() {
        let ((_, i1), (_, i2)) = pair_of(&bodies, row);
        push(&mut bodies, row.bodies, (i1, i2), row.lambda);
    }
}

/// Substep: the rows' pass after avian's biased contact solve.
pub(crate) fn solve_rows(mut rolling: ResMut<Rolling>, mut bodies: Bodies) {
    if !rolling.rows.is_empty() {
        solve(&mut rolling.rows, &mut bodies);
    }
}

/// Substep: the rows' pass after avian's relax pass; the substep's impulses are added to
/// the tick's.
pub(crate) fn relax_rows(mut rolling: ResMut<Rolling>, mut bodies: Bodies) {
    if rolling.rows.is_empty() {
        return;
    }
    solve(&mut rolling.rows, &mut bodies);
    for row in rolling.rows.iter_mut() {
        row.total += row.lambda;
    }
}

/// After the solve: the rows' impulses go to their pairs (the next tick's measurement and
/// warm start) and to the read-back.
pub(crate) fn collect(mut rolling: ResMut<Rolling>, mut read_back: ResMut<StickSlipRolling>) {
    let rolling = &mut *rolling;
    for row in &rolling.rows {
        if let Some(r) = rolling.pairs.get_mut(&row.pair) {
            r.impulse[row.kind] = add(r.impulse[row.kind], world_of(row.axis, row.total));
            r.last[row.kind] = add(r.last[row.kind], world_of(row.axis, row.lambda));
        }
    }
    // Read without writing while nothing resists (no change detection every tick).
    if rolling.pairs.is_empty() && read_back.0.is_empty() {
        return;
    }
    read_back.0.clear();
    if rolling.pairs.is_empty() {
        return;
    }
    let dt = rolling.dt as f32;
    let torque = |j: World| -> [f32; 3] {
        if dt > 0.0 {
            [j[0] / dt, j[1] / dt, j[2] / dt]
        } else {
            [0.0; 3]
        }
    };
    read_back.0.extend(
        rolling
            .pairs
            .iter()
            .filter(|(_, r)| r.seen == rolling.tick)
            .map(|(&(c1, c2), r)| {
                let mut report = RollingReport::new(c1, c2);
                report.point = r.point.to_array();
                report.normal = r.normal;
                report.normal_force = r.normal_force;
                report.rolling_arm = r.arm_roll;
                report.spinning_arm = r.arm_spin;
                if r.resists[0] {
                    report.rolling = r.roll.regime();
                    report.rolling_limit = r.roll.limit as f64;
                    report.rolling_torque = torque(r.impulse[0]);
                }
                if r.resists[1] {
                    report.spinning = r.spin.regime();
                    report.spinning_limit = r.spin.limit as f64;
                    report.spinning_torque = torque(r.impulse[1]);
                }
                report
            }),
    );
    read_back
        .0
        .sort_unstable_by_key(|r| (r.collider1.to_bits(), r.collider2.to_bits()));
}
