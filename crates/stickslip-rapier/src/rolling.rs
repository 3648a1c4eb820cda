//! Rolling and spinning resistance (3D): a torque against the relative rotation of two
//! touching bodies, M_r = μ_r R F_n against rolling and M_s = μ_spin a F_n against spinning,
//! each governed by a friction law of the pair's materials (see
//! [`stickslip_core::FrictionMaterial::rolling`]).
//!
//! **Mechanism.** rapier's contact hook can only write friction coefficients and target
//! velocities; it cannot apply a torque. So every touching pair whose materials ask for it
//! gets an impulse joint between its two bodies, with no locked axis (it constrains nothing
//! but what it resists, and leaves the contact to rapier) and three angular velocity motors
//! in a frame with y along the contact normal: x and z resist rolling, y spinning. Each motor
//! drives its component of the relative angular velocity to the law's target (zero unless a
//! law creeps), with its torque capped at the law's limit times arm times normal force. The
//! motors are rows of rapier's own solver, solved in the same iterations and substeps as the
//! contact's normal and friction rows, so the resisting torque, the contact's friction and
//! its normal force come out of one solve: a ball held on a slope is held by the friction
//! that stops it sliding and the torque that stops it rolling together, as a box is held by
//! friction alone.
//!
//! **The law.** Before each step the pair's rolling and spinning states are stepped by the
//! engine-free kernel (`step_contact`), exactly as a contact's friction is, on the rolled
//! arc: the "slip" is the arm times the relative angular velocity (its tangential part for
//! rolling, its normal part for spinning), the "measured friction" the motors' last impulse
//! over arm, normal impulse. So a hold is the kernel's hold: while the law sticks the motor is
//! rigid up to the law's capacity (the elasto-plastic break-away μ_ba) and nothing creeps;
//! beyond it the law yields and the motor brakes at the law's sliding level μ(R|ω|).
//!
//! **Arms.** From the shapes at the contact: R_i is the distance from body i's centre of mass
//! to the contact plane (a ball's radius, a cylinder's on its side), R = R₁R₂/(R₁+R₂) (a
//! fixed or kinematic body counts as infinitely large); a is the spread of the contact's points (their
//! largest distance from their centroid), or R for a single point.
//!
//! **What rolls.** A contact of one point (a ball) rolls about any axis of the contact plane;
//! a line of points (a cylinder on its side) only about the line: turning about the axis
//! across it lifts one end, which the contact's normal rows hold with the line's lever; a
//! patch (a box on its face) not at all. An axis counts as held by the normal rows when the
//! points reach farther across it than μ R (the law's break-away torque μ R F_n is then
//! within the normal forces' own moment); its motor is left free, so the normal rows carry
//! that turn alone, as in plain rapier.
//!
//! A collider without a body (a static ground) has its joint on a fixed body at the origin
//! that stickslip adds to the world once: rapier joins bodies only.
//!
//! **Normal force.** The last step's (the contact's normal impulse over the step), as the
//! friction limit's: the torque limit lags the load by one step.
//!
//! Rolling axes: x is kept along the rolling direction (or the last one while the contact
//! holds), so each motor's own cap is the law's limit along the way the load acts.
//!
//! **Read-back.** [`crate::StickSlip::rolling_reports`] gives each resisting pair's regimes,
//! torque caps and the torques the solver applied, from the motors' impulses after the step
//! (no extra work in the step), along the axes the step started with (the motors act in
//! collider 1's body frame: when that body turns, its axes turn by |ω₁| dt within the step). **Snapshots** keep the pairs' states and joint handles: a
//! restored world takes its joints over (see `adopt`).

use crate::fast_hash::HashMap;
use crate::measure::{measure, world_centroid};
use crate::report::{DIM, RollingReport};
#[cfg(not(dim2))]
use rapier::math::Mat3;
use rapier::prelude::*;
use std::borrow::Cow;
use stickslip_core::contact::ContactState;
use stickslip_core::law::{FrictionLaw, Law};
use stickslip_core::rolling::{AxisStep, Freedom, freedom, reduced_arm, step_axis};
#[cfg(not(dim2))]
use stickslip_core::rolling::{RollingInput, step_rolling};

/// Marks stickslip's joints (`GenericJoint::user_data`), so that a world restored from a
/// snapshot does not keep them twice.
pub(crate) const JOINT_TAG: u128 = 0x5354_4943_4b53_4c49_505f_524f_4c4c_0001;

/// A motor's damping: rigid (its row is a velocity constraint up to its torque cap).
const RIGID: f32 = 1e9;

/// The rolling and spinning laws of a pair: the materials' own (borrowed), or two sides'
/// combined.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct RotationLaws<'a> {
    pub rolling: Option<Cow<'a, Law>>,
    pub spinning: Option<Cow<'a, Law>>,
}

/// One resisting pair.
#[derive(Debug, Clone)]
// 2D resists rolling only.
#[cfg_attr(dim2, allow(dead_code))]
pub(crate) struct Resisting {
    pub joint: ImpulseJointHandle,
    pub roll: ContactState,
    pub spin: ContactState,
    /// The world axes the motors acted along in the last step (x: first rolling axis, y: the
    /// normal); zero before the first.
    pub axis_x: Vector,
    pub normal: Vector,
    /// The arms of the last step (m).
    pub arm_roll: f32,
    pub arm_spin: f32,
    /// The step it was last seen touching.
    pub seen: u64,
    /// The contact point and normal force (N) of the last step.
    pub point: Vector,
    pub normal_force: f64,
    /// Whether the pair's materials resisted rolling and spinning in the last step.
    pub resists: [bool; 2],
    /// The solver's substeps in the last step (a motor's impulse over the step is its last
    /// substep's times the substeps).
    pub substeps: usize,
}

/// A resisting pair with its colliders.
pub(crate) type ResistingPair = ((ColliderHandle, ColliderHandle), Resisting);

/// Every resisting pair's joint and states.
#[derive(Debug, Default)]
pub(crate) struct Rolling {
    pairs: HashMap<(ColliderHandle, ColliderHandle), Resisting>,
    step: u64,
    /// Joints of an earlier modifier (a restored snapshot's) were removed.
    adopted: bool,
    /// The fixed body the joints of colliders without a body hang from (rapier joins
    /// bodies only).
    anchor: Option<RigidBodyHandle>,
    /// The last step's length (s).
    pub dt: f64,
}

/// Sets a motor of `joint` to drive its axis' relative angular velocity to `target` with at
/// most `max` (N·m); a non-finite value leaves it free.
fn set_motor(joint: &mut GenericJoint, axis: JointAxis, max: f64, target: f64) {
    let (max, target) = if max.is_finite() && target.is_finite() {
        (max.max(0.0) as f32, target as f32)
    } else {
        (0.0, 0.0)
    };
    joint.set_motor_velocity(axis, target, RIGID);
    joint.set_motor_max_force(axis, max);
}

/// The distance from a body's centre of mass to the contact plane through `p` with normal
/// `n`; infinite for a fixed or kinematic body or none (the ground the other rolls on).
fn arm_of(bodies: &RigidBodySet, h: Option<RigidBodyHandle>, p: Vector, n: Vector) -> f32 {
    match h.and_then(|h| bodies.get(h)) {
        Some(b) if b.is_dynamic() => (p - b.center_of_mass()).dot(n).abs(),
        _ => f32::INFINITY,
    }
}

/// The largest inverse principal inertia of a body (0 for a fixed body or none).
fn inv_inertia(bodies: &RigidBodySet, h: Option<RigidBodyHandle>) -> f32 {
    match h.and_then(|h| bodies.get(h)) {
        Some(b) if b.is_dynamic() => {
            let inv = b.mass_properties().local_mprops.inv_principal_inertia;
            #[cfg(not(dim2))]
            let inv = inv.max_element();
            inv
        }
        _ => 0.0,
    }
}

/// How the points of `m` (their centroid `p`, normal `n`) let the bodies roll, and their
/// spread (largest distance from `p`), or `None` if a collider is gone. An axis is blocked
/// when the points reach farther than `lever` across it: the normal forces then carry the
/// law's break-away torque (μ R F_n = F_n × lever) on their own, and a motor beside them
/// would only share their load.
fn rolling_freedom(
    m: &ContactManifold,
    colliders: &ColliderSet,
    (c1, c2): (ColliderHandle, ColliderHandle),
    p: Vector,
    n: Vector,
    lever: f32,
) -> Option<(Freedom, f32)> {
    let pose = |h: ColliderHandle| colliders.get(h).map(|c| *c.position());
    let (pos1, pos2) = (pose(c1)?, pose(c2)?);
    let (pos1, pos2) = (
        m.subshape_pos1().map_or(pos1, |s| pos1 * *s),
        m.subshape_pos2().map_or(pos2, |s| pos2 * *s),
    );
    // In the contact plane, from the centroid.
    let offsets = || {
        m.data
            .solver_contacts
            .iter()
            .filter_map(|c| m.points.get(c.contact_indices()[0] as usize))
            .map(move |q| {
                let d = (pos1 * q.local_p1 + pos2 * q.local_p2) * 0.5 - p;
                crate::tangent::world(d - n * n.dot(d))
            })
    };
    Some(freedom(
        offsets,
        crate::tangent::world(n),
        lever,
        cfg!(not(dim2)),
    ))
}

impl Rolling {
    /// Heap bytes held (capacity included).
    pub fn heap_bytes(&self) -> usize {
        crate::heap::map_bytes(&self.pairs)
    }

    /// The body of a collider, or for one without, the anchor: a fixed body at the origin
    /// that stickslip adds to the world once (marked with [`JOINT_TAG`] as its `user_data`,
    /// and taken over from a restored world that has one).
    fn body_of(
        &mut self,
        bodies: &mut RigidBodySet,
        parent: Option<RigidBodyHandle>,
    ) -> RigidBodyHandle {
        if let Some(h) = parent {
            return h;
        }
        if let Some(h) = self.anchor.filter(|&h| bodies.get(h).is_some()) {
            return h;
        }
        let found = bodies
            .iter()
            .find(|(_, b)| b.user_data == JOINT_TAG && b.is_fixed())
            .map(|(h, _)| h);
        let h =
            found.unwrap_or_else(|| bodies.insert(RigidBodyBuilder::fixed().user_data(JOINT_TAG)));
        self.anchor = Some(h);
        h
    }

    /// Steps every touching pair `laws_of` gives rotation laws and sets its joint's motors
    /// for the coming step; removes the joints of pairs no longer touching.
    #[allow(clippy::too_many_arguments)]
    pub fn before_step<'a>(
        &mut self,
        joints: &mut ImpulseJointSet,
        substeps: usize,
        narrow_phase: &NarrowPhase,
        bodies: &mut RigidBodySet,
        colliders: &ColliderSet,
        dt: f64,
        time: f64,
        stiffness_time: f64,
        mut laws_of: impl FnMut(ColliderHandle, ColliderHandle) -> Option<RotationLaws<'a>>,
    ) {
        if !self.adopted {
            self.adopt(joints, bodies, colliders);
        }
        self.step = self.step.wrapping_add(1);
        // The last step's length: the motors' impulses were over it.
        let last_dt = if self.dt > 0.0 { self.dt } else { dt };
        self.dt = dt;
        let step = self.step;
        for pair in narrow_phase.contact_pairs() {
            if !pair.has_any_active_contact() {
                continue;
            }
            let (c1, c2) = (pair.collider1, pair.collider2);
            let Some(laws) = laws_of(c1, c2) else {
                continue;
            };
            let (Some(co1), Some(co2)) = (colliders.get(c1), colliders.get(c2)) else {
                continue;
            };
            if co1.parent().is_none() && co2.parent().is_none() {
                continue;
            }
            let (b1, b2) = (
                self.body_of(bodies, co1.parent()),
                self.body_of(bodies, co2.parent()),
            );
            if b1 == b2 {
                continue;
            }
            let bodies = &*bodies;
            // The manifold carrying the most of the pair's load.
            let Some(m) = pair
                .solver_manifolds()
                .iter()
                .filter(|m| !m.data.solver_contacts.is_empty())
                .max_by_key(|m| m.data.solver_contacts.len())
            else {
                continue;
            };
            let Some((p, _)) = world_centroid(m, colliders, (c1, c2)) else {
                continue;
            };
            let n = m.data.normal;
            let f_n = measure(m, &m.data.solver_contacts, dt, None).normal_force;
            let (r1, r2) = (
                arm_of(bodies, Some(b1), p, n),
                arm_of(bodies, Some(b2), p, n),
            );
            let arm_roll = reduced_arm(r1, r2);
            if !(arm_roll.is_finite() && arm_roll > 0.0) {
                continue;
            }
            // The contact's points (world, midway between the surfaces) and how they let the
            // bodies roll: a lever the law's break-away torque fits in makes an axis blocked.
            let lever = laws
                .rolling
                .as_ref()
                .map_or(0.0, |l| l.static_coefficient() as f32 * arm_roll);
            let Some((freedom, spread)) = rolling_freedom(m, colliders, (c1, c2), p, n, lever)
            else {
                continue;
            };
            #[cfg(not(dim2))]
            let arm_spin = if spread > 1e-3 * arm_roll {
                spread
            } else {
                arm_roll
            };
            #[cfg(dim2)]
            let arm_spin = {
                // No spinning in 2D: its arm is only reported.
                let _ = spread;
                arm_roll
            };
            let law_step = AxisStep {
                normal_force: f_n,
                dt,
                time,
                stiffness_time,
                inv_inertia: (inv_inertia(bodies, Some(b1)) + inv_inertia(bodies, Some(b2))) as f64,
            };
            // Stepped in place (one lookup, no copy).
            let (fresh, r) = match self.pairs.entry((c1, c2)) {
                std::collections::hash_map::Entry::Occupied(e) => (false, e.into_mut()),
                std::collections::hash_map::Entry::Vacant(e) => (
                    true,
                    e.insert(Resisting {
                        joint: ImpulseJointHandle::invalid(),
                        roll: ContactState::default(),
                        spin: ContactState::default(),
                        axis_x: Vector::ZERO,
                        normal: Vector::ZERO,
                        arm_roll,
                        arm_spin,
                        seen: step,
                        point: p,
                        normal_force: 0.0,
                        resists: [false; 2],
                        substeps: 1,
                    }),
                ),
            };
            // The motors' impulses over the last step (torque on body 2: −λ along each axis).
            // rapier keeps a motor's impulse of the last substep; the substeps are of equal
            // length.
            let last = joints.get(r.joint).filter(|_| !fresh);
            let impulse = |axis: JointAxis| {
                last.map_or(0.0, |j| j.data.motors[axis as usize].impulse) as f64
                    * r.substeps as f64
            };
            // Over the normal impulse the caps were set from: a cap the solve reached reads
            // as the law's limit, whatever the load did since.
            let normal_impulse = r.normal_force * last_dt;
            let mu_of = |lambda: f64, arm: f32| {
                if normal_impulse > 0.0 {
                    lambda / (arm as f64 * normal_impulse)
                } else {
                    0.0
                }
            };
            #[cfg(not(dim2))]
            let (set, axis_x) = {
                let (w1, w2) = (
                    bodies.get(b1).map_or(Vector::ZERO, |b| b.angvel()),
                    bodies.get(b2).map_or(Vector::ZERO, |b| b.angvel()),
                );
                let w = w2 - w1;
                // The last solve's resisting "friction" as a world vector, along the last
                // step's axes.
                let measured = crate::tangent::world(
                    r.axis_x * mu_of(impulse(JointAxis::AngX), r.arm_roll) as f32
                        + r.axis_x.cross(r.normal)
                            * mu_of(impulse(JointAxis::AngZ), r.arm_roll) as f32,
                );
                let command = step_rolling(
                    &mut r.roll,
                    laws.rolling.as_deref(),
                    &RollingInput {
                        freedom,
                        relative_angular_velocity: crate::tangent::world(w),
                        normal: crate::tangent::world(n),
                        arm: arm_roll,
                        last_axis: crate::tangent::world(r.axis_x),
                        measured,
                    },
                    law_step,
                );
                let axis_x = Vector::from(command.axis_x);
                let torque_spin = laws.spinning.as_ref().map_or((0.0, 0.0), |law| {
                    let measured = mu_of(impulse(JointAxis::AngY), r.arm_spin);
                    step_axis(&mut r.spin, law, arm_spin, n.dot(w), measured, law_step)
                });
                // The joint's frame: x, the normal as y, z = x × n; on each body, at the contact.
                let z = axis_x.cross(n);
                let world = Rotation::from_mat3(&Mat3::from_cols(axis_x, n, z));
                let frame = |h: RigidBodyHandle| {
                    bodies.get(h).map_or(Pose::IDENTITY, |b| {
                        let pose = b.position();
                        Pose::from_parts(
                            pose.inverse_transform_point(p),
                            pose.rotation.inverse() * world,
                        )
                    })
                };
                let (frame1, frame2) = (frame(b1), frame(b2));
                let motors = [
                    (JointAxis::AngX, command.caps[0], command.targets[0]),
                    (JointAxis::AngZ, command.caps[1], command.targets[1]),
                    (JointAxis::AngY, torque_spin.0, torque_spin.1),
                ];
                let set = move |j: &mut GenericJoint| {
                    j.set_local_frame1(frame1);
                    j.set_local_frame2(frame2);
                    for (axis, max, target) in motors {
                        set_motor(j, axis, max, target);
                    }
                };
                (set, axis_x)
            };
            // 2D: the relative rotation is all rolling, about the one angular axis (the
            // joint's frames do not matter to it).
            #[cfg(dim2)]
            let (set, axis_x) = {
                // Spinning needs a third dimension.
                let _ = &laws.spinning;
                let w = bodies.get(b2).map_or(0.0, |b| b.angvel())
                    - bodies.get(b1).map_or(0.0, |b| b.angvel());
                if freedom == Freedom::Blocked {
                    // A patch does not roll: its normal rows hold the turn, with their lever.
                    r.roll = ContactState::default();
                }
                let rolling = laws
                    .rolling
                    .as_ref()
                    .filter(|_| freedom != Freedom::Blocked);
                let (max, target) = rolling.map_or((0.0, 0.0), |law| {
                    let measured = mu_of(impulse(JointAxis::AngX), r.arm_roll);
                    step_axis(&mut r.roll, law, arm_roll, w, measured, law_step)
                });
                let set = move |j: &mut GenericJoint| set_motor(j, JointAxis::AngX, max, target);
                (set, Vector::ZERO)
            };
            match joints.get_mut(r.joint, false).filter(|_| !fresh) {
                Some(j) => set(&mut j.data),
                None => {
                    let mut j = GenericJoint::new(JointAxesMask::empty());
                    j.user_data = JOINT_TAG;
                    set(&mut j);
                    r.joint = joints.insert(b1, b2, j, false);
                }
            }
            r.axis_x = axis_x;
            r.normal = n;
            r.arm_roll = arm_roll;
            r.arm_spin = arm_spin;
            r.seen = step;
            r.point = p;
            r.normal_force = f_n;
            // rapier runs an island's extra iterations as extra substeps (the pair's bodies'
            // ask; a body elsewhere in the island asking more is not seen).
            let extra = |h: RigidBodyHandle| {
                bodies
                    .get(h)
                    .map_or(0, |b| b.additional_solver_iterations())
            };
            r.substeps = substeps + extra(b1).max(extra(b2));
            r.resists = [
                laws.rolling.is_some() && freedom != Freedom::Blocked,
                cfg!(not(dim2)) && laws.spinning.is_some(),
            ];
        }
        // Pairs that stopped touching (or resisting) lose their joint, in the pairs' order:
        // the order of removals decides the handles of joints inserted later, and so the
        // solver's order (a run and its resume from a snapshot stay bit-identical).
        let mut gone: Vec<_> = self
            .pairs
            .iter()
            .filter(|(_, r)| r.seen != step)
            .map(|(&k, _)| k)
            .collect();
        gone.sort_unstable_by_key(|&(a, b)| (a.into_raw_parts(), b.into_raw_parts()));
        for k in gone {
            if let Some(r) = self.pairs.remove(&k) {
                joints.remove(r.joint, false);
            }
        }
    }

    /// Takes over the joints of a restored world: those of the pairs this modifier was
    /// restored with keep their states; every other joint of stickslip's is removed (a
    /// snapshot without rolling states starts afresh).
    fn adopt(
        &mut self,
        joints: &mut ImpulseJointSet,
        bodies: &RigidBodySet,
        colliders: &ColliderSet,
    ) {
        // A joint joins the pair's bodies, or for a collider without one a fixed body of
        // stickslip's.
        let joins =
            |c: ColliderHandle, b: RigidBodyHandle| match colliders.get(c).map(|c| c.parent()) {
                Some(Some(parent)) => parent == b,
                Some(None) => bodies
                    .get(b)
                    .is_some_and(|b| b.user_data == JOINT_TAG && b.is_fixed()),
                None => false,
            };
        let mut taken = std::collections::HashSet::new();
        for (&(c1, c2), r) in self.pairs.iter_mut() {
            let ours = joints.get(r.joint).is_some_and(|j| {
                j.data.user_data == JOINT_TAG && joins(c1, j.body1()) && joins(c2, j.body2())
            });
            if !ours || !taken.insert(r.joint) {
                // Not this pair's joint (a world other than the snapshot's), or one another
                // pair took: a new one is inserted at the next step, with the pair's states.
                r.joint = ImpulseJointHandle::invalid();
            }
        }
        let kept: std::collections::HashSet<ImpulseJointHandle> =
            self.pairs.values().map(|r| r.joint).collect();
        let stale: Vec<_> = joints
            .iter()
            .filter(|(h, j)| j.data.user_data == JOINT_TAG && !kept.contains(h))
            .map(|(h, _)| h)
            .collect();
        for h in stale {
            joints.remove(h, false);
        }
        self.adopted = true;
    }

    /// The resisting pairs in collider order, with the step counter, for a snapshot.
    pub fn images(&self) -> (u64, Vec<ResistingPair>) {
        let mut images: Vec<_> = self.pairs.iter().map(|(&k, r)| (k, r.clone())).collect();
        images.sort_unstable_by_key(|((a, b), _)| (a.into_raw_parts(), b.into_raw_parts()));
        (self.step, images)
    }

    /// The state [`Self::images`] gave, with the last step's length: the joints of the
    /// world it is restored with are taken over at the next step (see `adopt`).
    pub fn from_images(
        step: u64,
        dt: f64,
        images: impl IntoIterator<Item = ResistingPair>,
    ) -> Self {
        Rolling {
            pairs: images.into_iter().collect(),
            step,
            adopted: false,
            anchor: None,
            dt,
        }
    }

    /// What the pairs resisting now did in the last step (see [`RollingReport`]), their
    /// torques from the motors' impulses in `joints`, in collider order.
    pub fn reports(&self, joints: &ImpulseJointSet) -> Vec<RollingReport> {
        let mut out: Vec<RollingReport> = self
            .pairs
            .iter()
            .filter(|(_, r)| r.seen == self.step)
            .map(|(&(c1, c2), r)| {
                // The step's angular impulse along each motor's axis; torque on body 2: −λ.
                let impulse = |axis: JointAxis| {
                    joints
                        .get(r.joint)
                        .map_or(0.0, |j| j.data.motors[axis as usize].impulse)
                        as f64
                        * r.substeps as f64
                };
                let torque = |axis: JointAxis, along: Vector| {
                    let t = if self.dt > 0.0 {
                        -impulse(axis) / self.dt
                    } else {
                        0.0
                    };
                    along * t as f32
                };
                #[cfg(not(dim2))]
                let (rolling_torque, spinning_torque) = {
                    let z = r.axis_x.cross(r.normal);
                    (
                        (torque(JointAxis::AngX, r.axis_x) + torque(JointAxis::AngZ, z)).to_array(),
                        torque(JointAxis::AngY, r.normal).to_array(),
                    )
                };
                #[cfg(dim2)]
                let (rolling_torque, spinning_torque) = {
                    let t = torque(JointAxis::AngX, Vector::new(1.0, 0.0)).x;
                    ([0.0, 0.0, t], [0.0; 3])
                };
                let [resists_rolling, resists_spinning] = r.resists;
                let mut report = RollingReport::new(c1, c2);
                report.point = crate::tangent::world(r.point)[..DIM]
                    .try_into()
                    .unwrap_or_default();
                report.normal = crate::tangent::world(r.normal)[..DIM]
                    .try_into()
                    .unwrap_or_default();
                report.normal_force = r.normal_force;
                report.rolling_arm = r.arm_roll;
                report.spinning_arm = r.arm_spin;
                if resists_rolling {
                    report.rolling = r.roll.regime();
                    report.rolling_limit = r.roll.limit as f64;
                    report.rolling_torque = rolling_torque;
                }
                if resists_spinning {
                    report.spinning = r.spin.regime();
                    report.spinning_limit = r.spin.limit as f64;
                    report.spinning_torque = spinning_torque;
                }
                report
            })
            .collect();
        out.sort_unstable_by_key(|r| (r.collider1.into_raw_parts(), r.collider2.into_raw_parts()));
        out
    }

    /// Whether no pair resists rotation now.
    pub fn is_empty(&self) -> bool {
        self.pairs.is_empty()
    }
}
