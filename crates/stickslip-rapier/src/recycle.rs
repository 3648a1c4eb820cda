//! Quiet contacts recycle.
//!
//! rapier skips contact determination for a pair whose relative pose barely moved since its
//! last full update (`IntegrationParameters::contact_recycling`): the pair keeps its points,
//! solver contacts, friction coefficient and target velocities. It never does so for a pair
//! with a hook flag on either collider, so a modifier that keeps its flag on every collider
//! makes every resting pair pay a full update, and re-picks its points every step (a plank
//! tower shimmers more than under plain rapier). stickslip therefore turns its own
//! `MODIFY_SOLVER_CONTACTS` flag off on an attached collider whose contacts are all *quiet*,
//! and on again before anything its hook would decide can change. The user's own flags are
//! never touched: a pair the user hooks stays hooked.
//!
//! ## A quiet contact, and why recycling it is the same physics
//! A contact is quiet when it holds (the solver's friction stayed below the limit, the law
//! sticks, the contact has formed and carries a load) or has no load and rests (see
//! `unloaded_at_rest`), and the hook's next step would write what the solver already has:
//! the same friction limit, to the bit, and no target velocity (over solver contacts that
//! have none). After each step [`StickSlip::end_step`] does that next step on a copy of
//! every record of a pair that could be recycled, with the inputs the hook would read (this
//! solve's normal force and friction, the slip of the touching points at the velocities
//! after it, the next step's clock), and keeps that step in the records of the pairs it lets
//! rapier recycle (after the reports, which tell the step just solved), marked as done: if a
//! later pair hooks one of the colliders again, the hook writes what that step found instead
//! of stepping twice (unless the collider was hooked again before the step, for something
//! the user changed: then the hook steps with what changed). A recycled manifold keeps what
//! the hook last wrote, and the solver reads it every step: the solve is the one a hooked step
//! would have made, and the record moves on exactly as the hook would have moved it (held
//! force, mean normal force, warm start). The one difference is rapier's own: a recycled pair
//! keeps its contact points instead of re-picking them, as in plain rapier.
//!
//! So a contact holding inside its limit is quiet (EP and Phys write their capacity, Coulomb
//! its μ), and so is an elasto-plastic contact with no load whose faces rest against each
//! other — a face touching at zero gap, common in towers built edge to edge, gets the law's
//! static coefficient every step. Before, such unloaded contacts were never quiet, and the
//! planks that carried them were hooked every step: 40 of the 445 colliders of a 444-plank
//! keva tower recycled, against 94–98 % now (`crates/stickslip-fixtures/tests/ordinary_stacks.rs` keeps that tower, once
//! settled, as still as plain rapier's). Contacts that slip, form or give stay hooked although their write
//! may repeat (a slide at a flat μ_k): recycled, a sliding cube on a compound ground and the
//! order of a pair's colliders made differences beyond plain rapier's own
//! (`crates/stickslip-fixtures/tests/ordinary_grounds.rs`, `crates/stickslip-fixtures/tests/shared_world.rs`).
//!
//! ## Pairs that move
//! rapier updates a recycled pair in full, without the hook, once its relative pose drifts
//! out of the recycle window or either collider turns by ~11.5° (rapier's rule). A pair whose
//! colliders barely move (at most [`MOTION_SHARE`] of the window a step) is hooked again
//! before that can happen (below). A pair with a collider that moves more — a box carried on
//! a platform, a stack in a turning drum, a ball rolling without slipping — may be recycled
//! too, when rapier's own full update would write what the hook writes: the pair's combined
//! friction coefficient (its colliders' coefficients by their combine rules) has the bits of
//! the law's limit, as for an elasto-plastic contact holding at μ_ba on colliders whose
//! friction is μ_ba. Its collider *rides* (if it touches something, through a pair found
//! quiet: one in flight stays hooked, its landing being a new contact): rapier updates its
//! pairs when it decides to, and no drift of its own hooks it again.
//!
//! ## Hooked again in time
//! A collider's flag goes back on (its pairs get a full, hooked update in the very next step)
//! when, after a step, one of its pairs that would not be hooked:
//! - would get another limit or a target velocity from the hook's next step (the solve
//!   saturated, a load changed what the law gives, a slip began): a hooked contact learns of
//!   a solve only at the next step too, from the same impulses;
//! - carries a manifold the hook did not write, with another limit than the law's (rapier
//!   ran a full update without the hook: a new contact patch, a collider the user changed);
//! - has nothing touching yet, a counterpart that moves against the other by more than
//!   [`MOTION_SHARE`] of the window a step, and their bounding boxes (with the contact
//!   skins) closer than rapier's prediction distance plus twice that motion: a contact may
//!   form in the coming step. rapier's detection at the start of the step sees the poses
//!   judged here; a body with soft CCD (predicted further by its velocity) keeps such pairs
//!   hooked, and with `max_ccd_substeps` > 1 (detections inside a step) the rule is off. A
//!   box carried past a wall or under a beam it does not reach stays recycled. A pair rapier
//!   has not found yet (its broad phase finds it a few centimetres early) is not judged: a
//!   counterpart faster than that gets its first update unhooked, as before;
//! - is filtered by the user (a pair-filter hook flag on either collider): rapier updates it
//!   in full at every step;
//! - moves (a collider that rides, see above) and its combined friction differs from the
//!   law's limit;
//!
//! or, for a collider that does not ride, when its body has drifted (plus the coming step's
//! motion) [`DRIFT_SHARE`] of the window since the flag went off
//! (checked in [`StickSlip::begin_step`], after any teleport or velocity the user set) —
//! rapier would otherwise run a full update on its own once the pair drifts out of the window
//! (the window is the prediction distance, or the recycle distance if smaller). A velocity
//! the user gives a collider that rides, or an *unattached* counterpart, between steps is
//! seen after the step; that step holds as a hooked contact would (the hook's hold reads the
//! last solve, not the velocity); a speed the kernel takes for garbage hooks it at once.
//! Or when the user changes the collider's material, a pair material, a vibration source or
//! the tuning, or attaches it again (also in `begin_step`); the hook then steps the record
//! `end_step` moved on, with what changed. A hooked manifold whose write changed marks its
//! colliders (those of moving bodies when there are any, so one sliding box does not hook a
//! whole ground), and so does a pair found not quiet after the step — unless one of them is
//! hooked at every step anyway (a vibration source or a moving surface on it), whose flag
//! alone keeps the pair hooked: the parts on a vibrating trough or a belt keep the recycling
//! of their pairs with each other, and rest on it rather than fly. Sleeping pairs are left
//! as they are: rapier does not update them.
//!
//! With `contact_recycling` off, or a pause (dt = 0), every flag stays on.
//!
//! ## Which pairs the pass reads
//! Only a pair with a candidate to go quiet (or an attached collider whose flag is the
//! user's) on a side can change anything: every other pair is hooked. When such colliders are
//! few (a world where only the ground or a conveyor is attached), the pass judges their pairs
//! alone, found through rapier's adjacency lists, instead of every pair rapier keeps; either
//! way in the order of rapier's list, so the decisions are the same (`pair_list`;
//! `crates/stickslip-fixtures/tests/rapier_recycling.rs`).
//!
//! ## On several threads
//! With rapier's `parallel` feature the pass after each step runs on rayon's threads (the
//! pool the step runs in): each thread takes batches of contact pairs from rapier's list and
//! judges them against the candidates found before the pass (the colliders that may go
//! quiet), stepping ahead the records of the pairs it finds quiet (a record is one pair's:
//! no two threads touch it). A pair with several touching manifolds or a composite shape is
//! left to the serial pass after it (their measurements go to one map). That serial pass
//! takes the findings in the order of rapier's list: a pair found not quiet hooks its
//! colliders again unless a pair before it already hooked one of them. So the flags are
//! those one thread going down the list sets, but for two things: a pair hooked by an
//! earlier one has had its next step done ahead, which the hook then writes (as for any
//! collider hooked again after the pass), and a collider that moves rests on every touching
//! pair found quiet, also one an earlier pair hooked (it touches something: it is not in
//! flight). One thread and two decide the same, bit for bit
//! (`crates/stickslip-fixtures/tests/rapier_recycling.rs`).

use crate::collider_map::{AtomicColliderBits, ColliderBits};
use crate::contact_store::is_composite;
use crate::contact_store::{ContactRecord, Records};
use crate::hook::inv_mass;
use crate::measure::{Measured, measure, point_velocity, world_centroid};
use crate::modifier::StickSlip;
use crate::pair_law::PairLaws;
use crate::quiet::{DRIFT_SHARE, MOTION_SHARE, QuietPose, QuietPoses};
use crate::warnings::Warned;
use rapier::prelude::*;
use stickslip_core::contact::{ContactInput, MAX_SANE_SPEED, slip_matters, step_contact};
use stickslip_core::law::Regime;

/// The fewest hook flags a step turns off (see `settle_after_step`).
const OFF_BUDGET: usize = 64;

/// A step turns off at most one in this many of stickslip's flags (or [`OFF_BUDGET`]).
const OFF_BUDGET_SHARE: usize = 32;

/// The pose the drift of `collider` is measured on (its body's, or its own without one) and
/// the collider's reach from that pose's origin.
fn anchor(bodies: &RigidBodySet, collider: &Collider) -> (Pose, f32) {
    let pose = pose_of(bodies, collider);
    let shape_reach = collider.shape().compute_local_bounding_sphere();
    let local = shape_reach.center.length() + shape_reach.radius;
    let offset = collider
        .position_wrt_parent()
        .map_or(0.0, |p| p.translation.length());
    (pose, local + offset)
}

/// The pose drift is measured on: the collider's body's, or its own without one.
fn pose_of(bodies: &RigidBodySet, collider: &Collider) -> Pose {
    match collider.parent().and_then(|h| bodies.get(h)) {
        Some(body) => *body.position(),
        None => *collider.position(),
    }
}

/// The collider's reach: remembered with its pose while it is quiet (a changed shape or
/// offset makes rapier run an unhooked full update, which hooks the collider again), found
/// from its shape otherwise.
fn reach_of(poses: &QuietPoses, bodies: &RigidBodySet, h: ColliderHandle, c: &Collider) -> f32 {
    match poses.get(h) {
        Some(q) => q.reach(),
        None => anchor(bodies, c).1,
    }
}

/// How far any point within `reach` of `a`'s origin moved to `b` (translation plus chord).
fn drift(a: &Pose, b: &Pose, reach: f32) -> f32 {
    // The chord is 2 r |sin(θ/2)|.
    let half_sin = half_turn_sine(a, b);
    (b.translation - a.translation).length() + 2.0 * half_sin * reach
}

/// |sin(θ/2)| of the rotation from `a` to `b`.
fn half_turn_sine(a: &Pose, b: &Pose) -> f32 {
    #[cfg(not(dim2))]
    {
        // The length of the quaternion's vector part.
        let turn = (b.rotation * a.rotation.inverse()).normalize();
        Vector::new(turn.x, turn.y, turn.z).length()
    }
    #[cfg(dim2)]
    {
        // cos θ of the turn, from the unit complexes: sin²(θ/2) = (1 − cos θ)/2.
        let cos = a.rotation.re * b.rotation.re + a.rotation.im * b.rotation.im;
        ((1.0 - cos).max(0.0) / 2.0).sqrt()
    }
}

/// The speed of the body's rotation (rad/s).
fn turn_rate(body: &RigidBody) -> f32 {
    #[cfg(not(dim2))]
    {
        body.angvel().length()
    }
    #[cfg(dim2)]
    {
        body.angvel().abs()
    }
}

/// How far the collider's material points can move in one step at the body's velocity.
fn step_motion(bodies: &RigidBodySet, collider: &Collider, reach: f32, dt: f32) -> f32 {
    match collider.parent().and_then(|h| bodies.get(h)) {
        Some(b) if !b.is_fixed() && !b.is_sleeping() => {
            (b.linvel().length() + turn_rate(b) * reach) * dt
        }
        _ => 0.0,
    }
}

/// Whether a contact without load rests: its touching points move against each other by no
/// more than the law's elastic range μ_s/c in a step. Such a contact (a face touching another
/// at zero gap, in a tower built edge to edge) gets the law's static coefficient every step
/// and may be recycled; one whose points move faster is landing or lifting off (a part
/// hopping on a feeder), and is hooked: recycled there, the landings of a hopping part went
/// 7 % slower than hooked ones (`crates/stickslip-fixtures/tests/rapier_feeder.rs`). A rigid law has no elastic range:
/// its unloaded contacts are hooked.
fn unloaded_at_rest(law: &stickslip_core::law::Law, relative: Vector, dt: f64) -> bool {
    use stickslip_core::law::FrictionLaw;
    law.stiffness()
        .is_some_and(|c| (relative.length() as f64) * dt <= law.static_coefficient() / c)
}

/// Stores `rec`, which holds the hook's next step, as its manifold's record (`at`: its
/// `user_data`, pair and the step's mark), and a composite patch's measurement for the next
/// hooked step.
fn commit_ahead(
    records: &Records,
    patches: Option<&mut crate::patches::PatchMeasures>,
    (user_data, c1, c2, mark): (u32, ColliderHandle, ColliderHandle, u32),
    mut rec: ContactRecord,
    meas: Option<Measured>,
) {
    rec.ahead = true;
    records.update(user_data, c1, c2, mark, |r| *r = rec);
    if let (Some(patches), Some(meas)) = (patches, meas) {
        patches.insert(user_data, meas);
    }
}

/// The bits of the friction coefficient rapier writes on the pair's manifolds when it
/// updates them in full without the hook (its colliders' coefficients by their combine
/// rules), if both colliders exist.
fn rapiers_own(colliders: &ColliderSet, c1: ColliderHandle, c2: ColliderHandle) -> Option<u32> {
    let (a, b) = (colliders.get(c1)?, colliders.get(c2)?);
    Some(crate::rapier_compat::combined_friction(a, b).to_bits())
}

/// How far the points of `c2` can move against `c1` in one step (m): the velocity of `c2`'s
/// centre of mass in `c1`'s moving frame, plus the turn between them at `c2`'s reach. Bodies
/// carried together (stacks on a platform, in a turning drum) barely move against each other.
fn relative_motion(
    bodies: &RigidBodySet,
    colliders: &ColliderSet,
    c1: ColliderHandle,
    c2: ColliderHandle,
    dt: f32,
) -> f32 {
    let frame = |h: ColliderHandle| {
        let c = colliders.get(h)?;
        let body = c.parent().and_then(|b| bodies.get(b));
        let (v, w, centre) = match body {
            Some(b) if !b.is_fixed() && !b.is_sleeping() => {
                (b.linvel(), b.angvel(), b.center_of_mass())
            }
            _ => (Vector::ZERO, AngVector::default(), c.position().translation),
        };
        // The turn is about the centre of mass: the reach from the body's origin, plus how
        // far the centre of mass sits from it.
        let (origin, reach) = anchor(bodies, c);
        Some((v, w, centre, reach + (centre - origin.translation).length()))
    };
    let (Some((v1, w1, o1)), Some((v2, w2, o2, reach2))) =
        (frame(c1).map(|(v, w, o, _)| (v, w, o)), frame(c2))
    else {
        return f32::INFINITY;
    };
    #[cfg(not(dim2))]
    let (carried, turn) = (v1 + w1.cross(o2 - o1), (w2 - w1).length());
    #[cfg(dim2)]
    let (carried, turn) = {
        let r = o2 - o1;
        (v1 + Vector::new(-w1 * r.y, w1 * r.x), (w2 - w1).abs())
    };
    ((v2 - carried).length() + turn * reach2) * dt
}

/// The collider's hook flags besides `MODIFY_SOLVER_CONTACTS` (the user's pair filters): with
/// any of them rapier updates every pair of the collider in full at every step.
fn user_bits(c: &Collider) -> ActiveHooks {
    c.active_hooks() - ActiveHooks::MODIFY_SOLVER_CONTACTS
}

/// Whether `c1` and `c2` stay farther apart than `reach` (m) beyond their contact skins: the
/// gap between their bounding boxes with the skins (a lower bound of the distance rapier
/// compares with its prediction distance) exceeds it. Never for a body with soft CCD, whose
/// pairs rapier predicts further by its velocity.
fn apart(
    bodies: &RigidBodySet,
    colliders: &ColliderSet,
    c1: ColliderHandle,
    c2: ColliderHandle,
    reach: f32,
) -> bool {
    let (Some(a), Some(b)) = (colliders.get(c1), colliders.get(c2)) else {
        return false;
    };
    let soft_ccd = |c: &Collider| {
        c.parent()
            .and_then(|h| bodies.get(h))
            .is_some_and(|b| b.soft_ccd_prediction() > 0.0)
    };
    if soft_ccd(a) || soft_ccd(b) {
        return false;
    }
    let (a, b) = (a.compute_collision_aabb(0.0), b.compute_collision_aabb(0.0));
    let gap = (a.mins - b.maxs).max(b.mins - a.maxs).max(Vector::ZERO);
    gap.length() > reach
}

/// Whether the collider's body is fixed (or it has none), or, with `or_asleep`, asleep.
fn is_still(
    bodies: &RigidBodySet,
    colliders: &ColliderSet,
    h: ColliderHandle,
    or_asleep: bool,
) -> bool {
    colliders
        .get(h)
        .and_then(|c| c.parent())
        .and_then(|b| bodies.get(b))
        .is_none_or(|b| b.is_fixed() || (or_asleep && b.is_sleeping()))
}

/// The attached colliders of a pair whose flag keeps the pair hooked: those of moving
/// bodies, or every attached one if none moves (both, not one: which one would depend on the
/// order rapier gives the pair in). `always`: whether stickslip hooks a collider at every
/// step.
fn hook_sides(
    attached: &ColliderBits,
    always: impl Fn(ColliderHandle) -> bool,
    bodies: &RigidBodySet,
    colliders: &ColliderSet,
    (c1, c2): (ColliderHandle, ColliderHandle),
) -> impl Iterator<Item = ColliderHandle> {
    let (a1, a2) = (attached.contains(c1), attached.contains(c2));
    // A side that is hooked at every step (a vibration source or a moving surface on it)
    // keeps the pair hooked alone: flagging the other would only take the recycling of that
    // collider's other pairs (the boxes on a vibrating plate).
    let (a1, a2) = if always(c1) || always(c2) {
        (false, false)
    } else {
        (a1, a2)
    };
    let (m1, m2) = (
        a1 && !is_still(bodies, colliders, c1, false),
        a2 && !is_still(bodies, colliders, c2, false),
    );
    let (k1, k2) = if m1 || m2 { (m1, m2) } else { (a1, a2) };
    [(c1, k1), (c2, k2)]
        .into_iter()
        .filter_map(|(h, keep)| keep.then_some(h))
}

/// What the pass over the contact pairs after a step found for one (see
/// `StickSlip::settle_after_step`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Judged {
    /// Nothing left to do: hooked, or quiet.
    Quiet,
    /// Not quiet (or filtered by the user): its colliders are hooked again.
    NotQuiet,
    /// Hooked or still, and touching a collider hooked at every step, on which its first,
    /// its second collider rests.
    Carries(bool, bool),
    /// Left to the serial pass: several touching manifolds, or a composite shape (their
    /// measurements are filed in a map).
    Left,
}

/// A contact pair, by its place in rapier's list of pairs, and what was found for it, in
/// 4 bytes: the place in the upper 29 bits (a list of 2²⁹ pairs would take rapier some
/// 100 GB), what was found in the lower 3.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Finding(u32);

impl Finding {
    fn new(pair: usize, what: Judged) -> Self {
        let code = match what {
            Judged::Quiet => 0,
            Judged::NotQuiet => 2,
            Judged::Carries(true, false) => 3,
            Judged::Carries(false, true) => 4,
            Judged::Carries(..) => 5,
            Judged::Left => 6,
        };
        let pair = u32::try_from(pair).map_or(u32::MAX >> 3, |p| p.min(u32::MAX >> 3));
        Finding(pair << 3 | code)
    }

    fn pair(self) -> usize {
        (self.0 >> 3) as usize
    }

    fn what(self) -> Judged {
        match self.0 & 7 {
            2 => Judged::NotQuiet,
            3 => Judged::Carries(true, false),
            4 => Judged::Carries(false, true),
            5 => Judged::Carries(true, true),
            6 => Judged::Left,
            _ => Judged::Quiet,
        }
    }
}

/// Contact pairs a thread of the pass takes from rapier's list at a time.
const BATCH: usize = 128;

/// Most parts (threads) of the pass.
const MAX_PARTS: usize = 64;

/// Judges the contact pairs (steps 2 and 3 of `StickSlip::settle_after_step`) into
/// `findings`, one list per part, each in the order of rapier's list of pairs: the pairs at
/// `places` in that list (increasing), or every pair. With the `parallel` feature a part runs
/// on each of rayon's threads, taking batches of pairs as it goes (so the work is shared
/// however its cost spreads over the list). A pair's finding depends on the pair and the
/// candidates in `next` alone, not on the part or the thread that judged it. `pairs`: rapier's
/// list, and `weight` the pair of one of its entries.
fn judge_pairs<E: Sync>(
    judge: &Judge,
    records: &Records,
    (pairs, weight): (&[E], impl Fn(&E) -> &ContactPair + Sync),
    places: Option<&[u32]>,
    next: &ColliderBits,
    findings: &mut Vec<Vec<Finding>>,
) {
    let count = places.map_or(pairs.len(), <[u32]>::len);
    let taken = std::sync::atomic::AtomicUsize::new(0);
    let judge_part = |out: &mut Vec<Finding>| {
        out.clear();
        loop {
            let start = taken.fetch_add(BATCH, std::sync::atomic::Ordering::Relaxed);
            if start >= count {
                break;
            }
            for k in start..count.min(start + BATCH) {
                let i = places.map_or(k, |p| p[k] as usize);
                let Some(entry) = pairs.get(i) else { continue };
                let what = judge.pair(weight(entry), next, records, None);
                if what != Judged::Quiet {
                    out.push(Finding::new(i, what));
                }
            }
        }
        // What a burst of findings (a tower settling) left is given back, with room to spare
        // so that a list which merely varies keeps its memory.
        if out.capacity() > 4 * out.len() + 256 {
            out.shrink_to(2 * out.len() + 64);
        }
    };
    #[cfg(feature = "parallel")]
    let parts = rayon::current_num_threads().clamp(1, MAX_PARTS);
    #[cfg(not(feature = "parallel"))]
    let parts = 1;
    // Parts are kept (with their memory) when fewer are needed.
    if findings.len() < parts {
        findings.resize_with(parts, Vec::new);
    }
    for out in &mut findings[parts..] {
        out.clear();
    }
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        findings[..parts].par_iter_mut().for_each(judge_part);
    }
    #[cfg(not(feature = "parallel"))]
    judge_part(&mut findings[0]);
}

/// The findings of every part, merged in the order of rapier's list of pairs.
struct InOrder<'a> {
    parts: &'a [Vec<Finding>],
    at: [usize; MAX_PARTS],
}

impl<'a> InOrder<'a> {
    fn new(parts: &'a [Vec<Finding>]) -> Self {
        InOrder {
            parts: &parts[..parts.len().min(MAX_PARTS)],
            at: [0; MAX_PARTS],
        }
    }
}

impl Iterator for InOrder<'_> {
    type Item = Finding;

    fn next(&mut self) -> Option<Finding> {
        let (k, f) = self
            .parts
            .iter()
            .enumerate()
            .filter_map(|(k, part)| part.get(self.at[k]).map(|f| (k, *f)))
            .min_by_key(|(_, f)| f.pair())?;
        self.at[k] += 1;
        Some(f)
    }
}

/// What judging a contact pair after a step reads (all of it shared by the threads of the
/// pass): the hook's next step, the candidates to go quiet and the colliders' motion.
struct Judge<'a> {
    ahead: Ahead<'a>,
    attached: &'a ColliderBits,
    flagged: &'a ColliderBits,
    /// Colliders stickslip hooks at every step.
    always: &'a ColliderBits,
    /// Colliders that move and touch through a pair found quiet (set by the pass's threads;
    /// sized for the colliders that move).
    carried: &'a AtomicColliderBits,
    still: &'a ColliderBits,
    moving: &'a ColliderBits,
    bodies: &'a RigidBodySet,
    colliders: &'a ColliderSet,
    clustering: bool,
    step_limit: f32,
    prediction: f32,
    mark: u32,
}

impl Judge<'_> {
    /// Whether the pair is hooked at the next step with the quiet set `next`.
    #[inline]
    fn hooked(&self, pair: &ContactPair, next: &ColliderBits) -> bool {
        let (c1, c2) = (pair.collider1, pair.collider2);
        let (a1, a2) = (self.attached.contains(c1), self.attached.contains(c2));
        !(a1 || a2) || self.hooked_next(c1, a1, next) || self.hooked_next(c2, a2, next)
    }

    #[inline]
    fn hooked_next(&self, h: ColliderHandle, attached: bool, next: &ColliderBits) -> bool {
        if attached && self.flagged.contains(h) {
            !next.contains(h)
        } else {
            self.colliders.get(h).is_some_and(|c| {
                c.active_hooks()
                    .contains(ActiveHooks::MODIFY_SOLVER_CONTACTS)
            })
        }
    }

    #[inline]
    fn is_still_now(&self, h: ColliderHandle) -> bool {
        if self.flagged.contains(h) {
            self.still.contains(h)
        } else {
            is_still(self.bodies, self.colliders, h, true)
        }
    }

    #[inline]
    fn moves(&self, h: ColliderHandle) -> bool {
        if self.flagged.contains(h) {
            self.moving.contains(h)
        } else {
            self.colliders.get(h).is_some_and(|c| {
                let (_, reach) = anchor(self.bodies, c);
                step_motion(self.bodies, c, reach, self.ahead.dt as f32) > self.step_limit
            })
        }
    }

    /// The attached colliders of the pair whose flag keeps it hooked (see [`hook_sides`]).
    fn sides_to_hook(
        &self,
        c1: ColliderHandle,
        c2: ColliderHandle,
    ) -> impl Iterator<Item = ColliderHandle> {
        let always = |h| self.always.contains(h);
        hook_sides(self.attached, always, self.bodies, self.colliders, (c1, c2))
    }

    /// Judges a pair with the quiet set `next` and steps ahead the records of its manifolds
    /// if they are quiet. Without `patches` (the parallel pass), a pair with several touching
    /// manifolds or a composite shape is [`Judged::Left`] untouched.
    fn pair(
        &self,
        pair: &ContactPair,
        next: &ColliderBits,
        records: &Records,
        patches: Option<&mut crate::patches::PatchMeasures>,
    ) -> Judged {
        let (bodies, colliders, mark) = (self.bodies, self.colliders, self.mark);
        let (c1, c2) = (pair.collider1, pair.collider2);
        let (a1, a2) = (self.attached.contains(c1), self.attached.contains(c2));
        let hooked = self.hooked(pair, next);
        // A pair the user filters (a filter flag on an unattached collider) is updated in full
        // at every step, also once its bodies sleep and are woken: it stays hooked.
        // (A candidate still to go quiet had none in 1.: only the other colliders are looked
        // up, which spares the pile's resting pairs two reads of the arena.)
        let filtered = !hooked
            && [(c1, a1), (c2, a2)].into_iter().any(|(h, attached)| {
                !(attached && self.flagged.contains(h) && next.contains(h))
                    && colliders.get(h).is_some_and(|c| !user_bits(c).is_empty())
            });
        if filtered {
            return Judged::NotQuiet;
        }
        let touches = || {
            pair.solver_manifolds()
                .iter()
                .any(|m| !m.data.solver_contacts.is_empty())
        };
        if hooked || (self.is_still_now(c1) && self.is_still_now(c2)) {
            // A collider touching one hooked at every step (a vibrating plate, a belt) rests
            // on it: it is not in flight. (Only a collider that moves needs to know.)
            let rests = |h, on| self.moving.contains(h) && self.always.contains(on);
            let first = rests(c1, c2) && touches();
            let second = rests(c2, c1) && touches();
            return if first || second {
                Judged::Carries(first, second)
            } else {
                Judged::Quiet
            };
        }
        let pair_moves = self.moves(c1) || self.moves(c2);
        // Rapier's own full update of a pair that moves writes the pair's combined friction
        // coefficient and no target velocity.
        let own = pair_moves.then(|| rapiers_own(colliders, c1, c2)).flatten();
        // The touching manifolds must each be written the same by the hook's next step (and,
        // for a pair that moves, by rapier's own full update).
        let keeps = |rec: &ContactRecord, same: bool| {
            same && (!pair_moves || own == Some(rec.state.limit.to_bits()))
        };
        // Asked only of touching pairs (a shape is behind a pointer).
        let composite = || {
            self.clustering
                && [c1, c2]
                    .into_iter()
                    .any(|h| colliders.get(h).is_some_and(|c| is_composite(c.shape())))
        };
        // A touching pair found quiet carries its colliders: they are not in flight (only
        // those that move are asked, see `settle_after_step`).
        let quiet_or_not = |quiet: bool| {
            if !quiet {
                return Judged::NotQuiet;
            }
            for h in [c1, c2] {
                if self.moving.contains(h) {
                    self.carried.set(h);
                }
            }
            Judged::Quiet
        };
        let mut touching = pair
            .solver_manifolds()
            .iter()
            .filter(|m| !m.data.solver_contacts.is_empty());
        match (touching.next(), touching.next()) {
            // Nothing touches yet: a counterpart that moves towards the other may make a
            // contact rapier would form without the hook, unless the two stay farther apart
            // than rapier's prediction distance over the coming step, by twice their relative
            // motion in a step (the pair is judged again after it).
            (None, _) => {
                let quiet = !pair_moves || {
                    let motion = relative_motion(bodies, colliders, c1, c2, self.ahead.dt as f32);
                    motion <= self.step_limit
                        || apart(bodies, colliders, c1, c2, self.prediction + 2.0 * motion)
                };
                if quiet {
                    Judged::Quiet
                } else {
                    Judged::NotQuiet
                }
            }
            // One manifold (the common case): stepped in place, and kept if quiet (3.).
            (Some(m), None) => {
                let composite = composite();
                if composite && patches.is_none() {
                    return Judged::Left;
                }
                let ud = m.data.user_data;
                let kept = records.update(ud, c1, c2, mark, |rec| {
                    let before = *rec;
                    let (same, meas) = self.ahead.step(m, (c1, c2), bodies, colliders, rec);
                    if keeps(rec, same) {
                        rec.ahead = true;
                        Some(meas)
                    } else {
                        *rec = before;
                        None
                    }
                });
                let kept = kept.flatten();
                if let (Some(Some(meas)), true, Some(patches)) = (kept, composite, patches) {
                    patches.insert(ud, meas);
                }
                quiet_or_not(kept.is_some())
            }
            // Several: each tried on a copy, then stepped for good if all are quiet.
            _ => {
                let Some(patches) = patches else {
                    return Judged::Left;
                };
                let all = pair.solver_manifolds().iter().all(|m| {
                    m.data.solver_contacts.is_empty()
                        || records
                            .touch(m.data.user_data, c1, c2, mark)
                            .is_some_and(|mut rec| {
                                let (same, _) =
                                    self.ahead.step(m, (c1, c2), bodies, colliders, &mut rec);
                                keeps(&rec, same)
                            })
                });
                if all {
                    let composite = composite();
                    let mut patches = composite.then_some(patches);
                    for m in pair.solver_manifolds() {
                        if m.data.solver_contacts.is_empty() {
                            continue;
                        }
                        let Some(mut rec) = records.touch(m.data.user_data, c1, c2, mark) else {
                            continue;
                        };
                        let (_, meas) = self.ahead.step(m, (c1, c2), bodies, colliders, &mut rec);
                        let at = (m.data.user_data, c1, c2, mark);
                        commit_ahead(records, patches.as_deref_mut(), at, rec, meas);
                    }
                }
                quiet_or_not(all)
            }
        }
    }
}

/// What the hook's next step on a recycled manifold needs besides the manifold: the pairs'
/// laws, the next step's clock and the tuning (borrowed apart from the contact store, which
/// takes the step).
struct Ahead<'a> {
    laws: &'a PairLaws,
    attached: &'a ColliderBits,
    warned: &'a Warned,
    dt: f64,
    time: f64,
    stiffness_time: f64,
}

impl Ahead<'_> {
    /// The hook's next step on a manifold, done on `rec` now, after the solve: the kernel
    /// with the inputs the hook reads at the next step (this solve's normal force and
    /// friction, the slip of the touching points at the velocities after it, the next step's
    /// clock), as when rapier recycles the manifold (its points kept, so its warm start
    /// whole). Returns whether that step writes what the solver already has — the same
    /// limit, to the bit, and no target velocity, over solver contacts that have none — and
    /// the measurement.
    fn step(
        &self,
        m: &ContactManifold,
        pair: (ColliderHandle, ColliderHandle),
        bodies: &RigidBodySet,
        colliders: &ColliderSet,
        rec: &mut ContactRecord,
    ) -> (bool, Option<Measured>) {
        let dt = self.dt;
        let (rb1, rb2) = (m.data.rigid_body1, m.data.rigid_body2);
        let basis = crate::tangent::basis(m.data.normal);
        let meas = measure(
            m,
            &m.data.solver_contacts,
            dt,
            crate::rapier_compat::warm_before(rec),
        );
        crate::rapier_compat::remember_warm_start(rec, meas.warm_start_impulse);
        let measured_mu = basis.project(crate::tangent::world(meas.mu));
        let unloaded = !(meas.normal_force > 0.0);
        let step = self
            .laws
            .with_pair_law(self.attached, colliders, pair, self.warned, |law| {
                // The touching points' motion, only where the step reads it (a held contact
                // is held whatever it slips).
                let motion = if unloaded
                    || slip_matters(&rec.state, law, None, meas.normal_force, measured_mu)
                {
                    let (p, surface) = world_centroid(m, colliders, pair)?;
                    let relative =
                        point_velocity(bodies, rb2, p) - point_velocity(bodies, rb1, p) - surface;
                    let at_rest = unloaded && unloaded_at_rest(law, relative, dt);
                    let inv = inv_mass(bodies, rb1) + inv_mass(bodies, rb2);
                    (basis.project(crate::tangent::world(relative)), inv, at_rest)
                } else {
                    ([0.0; 2], 0.0, false)
                };
                let (slip, inv_mass, at_rest) = motion;
                let out = step_contact(
                    &mut rec.state,
                    &ContactInput::new(law, &basis, dt)
                        .with_solve(meas.normal_force, measured_mu, slip)
                        .at_time(self.time)
                        .with_inv_mass(inv_mass)
                        .with_stiffness_time(self.stiffness_time),
                );
                Some((out, at_rest))
            });
        let Some((out, at_rest)) = step else {
            return (false, None);
        };
        // Held (the solver's friction stayed below the limit, and the law sticks), formed,
        // or without load and at rest; a slipping, forming or giving contact is the hook's.
        let held = out.holding
            && rec.state.forming == 0
            && rec.state.regime == Regime::Sticking.code()
            && !unloaded;
        let same = (held || at_rest)
            && rec.state.limit.to_bits() == m.data.friction.to_bits()
            && out.target == [0.0; 2]
            && m.data
                .solver_contacts
                .iter()
                .all(|c| c.tangent_velocity == Vector::ZERO);
        (same, Some(meas))
    }
}

impl<H> StickSlip<H> {
    /// Marks the colliders a hooked manifold whose write changed keeps hooked: those of
    /// moving bodies among its attached ones (all attached ones if none moves).
    pub(crate) fn mark_active(
        &self,
        bodies: &RigidBodySet,
        colliders: &ColliderSet,
        c1: ColliderHandle,
        c2: ColliderHandle,
    ) {
        for h in self.sides_to_hook(bodies, colliders, c1, c2) {
            self.recycling.active.set(h);
        }
    }

    /// Whether stickslip hooks `h` at every step: a collider with its flag and a vibration
    /// source or a moving surface is never quiet (see `settle_after_step`).
    fn always_hooked(&self, h: ColliderHandle) -> bool {
        self.flagged.contains(h)
            && (self.vibrations.get(h).is_some() || self.surfaces.get(h).is_some())
    }

    /// The attached colliders of a pair whose flag keeps the pair hooked (see
    /// [`hook_sides`]).
    fn sides_to_hook(
        &self,
        bodies: &RigidBodySet,
        colliders: &ColliderSet,
        c1: ColliderHandle,
        c2: ColliderHandle,
    ) -> impl Iterator<Item = ColliderHandle> {
        let always = |h| self.always_hooked(h);
        hook_sides(&self.attached, always, bodies, colliders, (c1, c2))
    }

    /// Before a step: hooks again the quiet colliders that were asked to be (changed
    /// materials or sources), or whose body drifted (see the module docs).
    pub(crate) fn wake_before_step(&mut self, bodies: &RigidBodySet, colliders: &mut ColliderSet) {
        let dt = self.clock.dt as f32;
        let r = &mut self.recycling;
        let limit = DRIFT_SHARE * r.window;
        let step_limit = MOTION_SHARE * r.window;
        let mut woken = std::mem::take(&mut r.next);
        woken.clear();
        for i in r.quiet.indices() {
            let Some((c, h)) = colliders.get_unknown_gen(i) else {
                continue;
            };
            // Drifted, or given a velocity (by the user, between steps) that leaves the window.
            // A collider that rides (moves more than a step's share of the window, see
            // `settle_after_step`) is left to rapier: its pairs' full updates write the same.
            let moved = r.poses.get(h).is_none_or(|q| {
                let reach = q.reach();
                let motion = step_motion(bodies, c, reach, dt);
                if motion > step_limit {
                    // Unless the user gave it a speed that is garbage (the kernel resets).
                    !(motion <= MAX_SANE_SPEED as f32 * dt)
                } else {
                    let now = QuietPose::new(&pose_of(bodies, c), reach);
                    // A bound first (see `QuietPose::surely_within`); it decides as the
                    // measured drift does where it tells.
                    #[cfg(not(dim2))]
                    let sure = q.surely_within(&now, reach, motion, limit);
                    #[cfg(dim2)]
                    let sure = false;
                    !(sure || drift(&q.pose(), &now.pose(), reach) + motion <= limit)
                }
            });
            // A filter flag the user set between steps: rapier updates its pairs in full.
            let filtered = !user_bits(c).is_empty();
            if r.wake_all || r.wake.contains(h) || moved || filtered || !(r.window > 0.0) {
                woken.set(h, true);
            }
        }
        let mut any = false;
        for i in woken.indices() {
            if let Some((c, h)) = colliders.get_unknown_gen_mut(i) {
                c.set_active_hooks(c.active_hooks() | ActiveHooks::MODIFY_SOLVER_CONTACTS);
                r.quiet.set(h, false);
                any = true;
            }
        }
        if any {
            // Their poses, in one pass.
            r.poses.retain(|i| r.quiet.contains_index(i));
        }
        r.next = woken;
        r.wake.clear();
        r.wake_all = false;
    }

    /// After a step: decides which attached colliders go quiet or are hooked again, reads
    /// the solve of the manifolds that will be recycled and updates their records as the
    /// hook would, and sets the flags (see the module docs).
    pub(crate) fn settle_after_step(
        &mut self,
        narrow_phase: &NarrowPhase,
        bodies: &RigidBodySet,
        colliders: &mut ColliderSet,
        mark: u32,
    ) {
        // What the last `end_step` did ahead was for the step just solved.
        self.store.clear_ahead();
        let window = self.recycling.window;
        let dt = self.clock.dt;
        if !(window > 0.0 && dt > 0.0) {
            self.recycling.active.clear();
            if !(window > 0.0) {
                self.recycling.wake_all = true;
            }
            return;
        }
        let mut next = std::mem::take(&mut self.recycling.next);
        next.clear();
        let mut still = std::mem::take(&mut self.recycling.still);
        still.clear();
        let mut moving = std::mem::take(&mut self.recycling.moving);
        moving.clear();
        let mut carried = std::mem::take(&mut self.recycling.carried);
        carried.clear();
        let mut always = std::mem::take(&mut self.recycling.always);
        always.clear();
        // 1. Colliders that may go (or stay) quiet: stickslip's flag, not marked by the hook,
        //    no source, a body that barely moves.
        let step_limit = MOTION_SHARE * window;
        let prediction = self.recycling.prediction;
        for i in self.flagged.indices() {
            let Some((c, h)) = colliders.get_unknown_gen(i) else {
                continue;
            };
            // Only candidates need their motion: the pairs of the others stay hooked. So
            // does a collider with a hook flag of the user's besides stickslip's (a pair
            // filter): rapier never recycles its pairs, and without stickslip's flag their
            // full updates would get rapier's friction.
            // Hooked at every step: a source or a moving surface on it.
            if self.vibrations.get(h).is_some() || self.surfaces.get(h).is_some() {
                always.set(h, true);
                continue;
            }
            if !self.attached.contains(h)
                || !user_bits(c).is_empty()
                || self.recycling.active.contains(h)
            {
                continue;
            }
            let body = c.parent().and_then(|b| bodies.get(b));
            if body.is_none_or(|b| b.is_fixed() || b.is_sleeping()) {
                still.set(h, true);
                next.set(h, true);
                continue;
            }
            // A moving collider may be quiet too: its pairs then need that rapier's own full
            // update, whenever rapier decides on one, writes what the hook would (see
            // `rapiers_own`).
            let reach = reach_of(&self.recycling.poses, bodies, h, c);
            next.set(h, true);
            if step_motion(bodies, c, reach, dt as f32) > step_limit {
                moving.set(h, true);
                // Only a collider that moves needs to know it rides.
                carried.cover(h);
            }
        }
        // 2. Every pair of stickslip's that will not be hooked: its manifolds must be quiet.
        //    Each pair is judged against the candidates of 1. (the same for every pair, in
        //    whatever order and on whatever thread), and
        // 3. the hook's next step is done now on the manifolds to be recycled and kept in
        //    their records, marked: if a pair hooks one of the colliders again (below, or the
        //    hook at the next step), the hook writes what this step found instead of stepping
        //    twice. Pairs with several touching manifolds or a composite shape are left to
        //    the serial pass (they file what they measure).
        let judge = Judge {
            ahead: Ahead {
                laws: &self.laws,
                attached: &self.attached,
                warned: &self.warned,
                dt,
                time: self.clock.time,
                stiffness_time: self.config.stiffness_time,
            },
            attached: &self.attached,
            flagged: &self.flagged,
            always: &always,
            carried: &carried,
            still: &still,
            moving: &moving,
            bodies,
            colliders: &*colliders,
            clustering: self.clock.clustering,
            step_limit,
            prediction,
            mark,
        };
        let records = self.store.records();
        let mut findings = std::mem::take(&mut self.recycling.findings);
        // Only the pairs whose finding can change something (see `pair_list`).
        let mut list = std::mem::take(&mut self.recycling.pairs);
        let bits = (&next, &self.attached, &self.flagged);
        list.choose(narrow_phase, colliders, bits, self.recycling.walk);
        let pairs = narrow_phase.contact_graph().raw_graph().raw_edges();
        let listed = list.places();
        judge_pairs(
            &judge,
            &records,
            (pairs, |e| &e.weight),
            listed,
            &next,
            &mut findings,
        );
        // 4. In the order of the pairs: a pair not quiet hooks its colliders again (those of
        //    moving bodies), unless an earlier pair already did; a pair found quiet carries its
        //    colliders.
        for f in InOrder::new(&findings) {
            let Some(entry) = pairs.get(f.pair()) else {
                continue;
            };
            let pair = &entry.weight;
            let what = match f.what() {
                Judged::Left => judge.pair(pair, &next, &records, Some(&mut self.patches_measured)),
                // Hooked since by a pair before it (as if judged in this order).
                Judged::NotQuiet if judge.hooked(pair, &next) => Judged::Quiet,
                what => what,
            };
            let (c1, c2) = (pair.collider1, pair.collider2);
            match what {
                Judged::NotQuiet => {
                    for h in judge.sides_to_hook(c1, c2) {
                        next.set(h, false);
                    }
                }
                Judged::Carries(first, second) => {
                    for (h, carries) in [(c1, first), (c2, second)] {
                        if carries {
                            judge.carried.set(h);
                        }
                    }
                }
                Judged::Quiet | Judged::Left => {}
            }
        }
        self.recycling.findings = findings;
        self.recycling.pairs = list;
        // A collider that moves rides only on something it touches: one in flight is hooked
        // (its landing is a new contact, rapier would form it without the hook).
        for i in moving.indices() {
            if let Some((_, h)) = colliders.get_unknown_gen(i)
                && !carried.contains(h)
            {
                next.set(h, false);
            }
        }
        // 4. The flags. Turning a flag off takes the collider mutably, which makes rapier
        //    queue it and every contact pair it has (`NarrowPhase`'s forced-event list); those
        //    buffers keep their size for ever. So a step turns off at most `off_budget` flags,
        //    the lowest indices first: a settling pile goes quiet over some steps, not in one
        //    (the bench's 10 000-point pile: the world's heap over plain rapier's fell from
        //    213 to 111 B per contact). Flags going on are never held back.
        let r = &mut self.recycling;
        let mut off_budget = OFF_BUDGET.max(self.flagged.count() / OFF_BUDGET_SHARE);
        let mut hooked_again = false;
        for i in self.flagged.indices() {
            // Read first: taking a collider mutably marks it modified, and rapier then
            // re-processes it (and its pairs) in the next step.
            let Some((_, h)) = colliders.get_unknown_gen(i) else {
                continue;
            };
            let (now, then) = (r.quiet.contains(h), next.contains(h));
            if now == then {
                continue;
            }
            if then {
                if off_budget == 0 {
                    // Stays hooked this step: its records were stepped ahead, which the hook
                    // then writes (see `commit_ahead`).
                    next.set(h, false);
                    continue;
                }
                off_budget -= 1;
            }
            let Some(c) = colliders.get_mut(h) else {
                continue;
            };
            if then {
                c.set_active_hooks(c.active_hooks() - ActiveHooks::MODIFY_SOLVER_CONTACTS);
            } else {
                c.set_active_hooks(c.active_hooks() | ActiveHooks::MODIFY_SOLVER_CONTACTS);
                hooked_again = true;
            }
        }
        if hooked_again {
            // Their poses go, in one pass.
            r.poses.retain(|i| next.contains_index(i));
        }
        for i in next.indices() {
            let Some((c, h)) = colliders.get_unknown_gen(i) else {
                continue;
            };
            // A quiet collider that moves rides: rapier updates its pairs in full whenever
            // it decides to, and that writes what the hook would. One that barely moves is
            // hooked again before rapier would update its pairs without the hook.
            // Its pose is kept current, so it is hooked again only if it stops and then
            // drifts.
            if moving.contains(h) || !r.quiet.contains(h) {
                // A collider that stays quiet keeps its reach (a changed shape makes rapier
                // update its pairs unhooked, which hooks it again).
                r.poses.update(h, |kept| {
                    let (pose, reach) = match kept {
                        Some(q) => (pose_of(bodies, c), q.reach()),
                        None => anchor(bodies, c),
                    };
                    QuietPose::new(&pose, reach)
                });
            }
        }
        r.next = std::mem::replace(&mut r.quiet, next);
        r.still = still;
        r.moving = moving;
        r.carried = carried;
        r.always = always;
        r.active.clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_finding_keeps_its_pair_and_what_was_found() {
        let all = [
            Judged::NotQuiet,
            Judged::Carries(true, false),
            Judged::Carries(false, true),
            Judged::Carries(true, true),
            Judged::Left,
        ];
        for pair in [0, 1, 4095, (1 << 29) - 2] {
            for what in all {
                let f = Finding::new(pair, what);
                assert_eq!((f.pair(), f.what()), (pair, what));
            }
        }
    }

    #[test]
    fn drift_adds_the_rotation_chord_at_the_reach() {
        let a = Pose::from_translation(crate::tangent::vector([1.0, 2.0, 3.0]));
        let mut b = a;
        b.translation.x += 0.001;
        assert!((drift(&a, &b, 10.0) - 0.001).abs() < 1e-6);
        // A quarter turn: chord 2 r sin(π/4) = √2 r.
        #[cfg(not(dim2))]
        let quarter = Rotation::from_axis_angle(Vector::Y, std::f32::consts::FRAC_PI_2);
        #[cfg(dim2)]
        let quarter = Rotation::new(std::f32::consts::FRAC_PI_2);
        let b = Pose::from_parts(a.translation, quarter);
        assert!((drift(&a, &b, 2.0) - 2.0 * std::f32::consts::SQRT_2).abs() < 1e-5);
    }

    /// Over kept poses of every orientation and bodies turned and moved from them by amounts
    /// from nothing to far beyond the limit (a fixed sequence), at reaches from 1 cm to 50 m:
    /// wherever the bound says a body is within the limit, the measured drift says so too;
    /// and it tells for most bodies that barely moved (else it would save nothing).
    #[cfg(not(dim2))]
    #[test]
    fn the_drift_bound_decides_as_the_measured_drift() {
        let mut next = crate::quiet::uniform_sequence(0x2545_F491_4F6C_DD1D);
        let (mut told, mut small, mut agreed) = (0, 0, 0);
        for k in 0..40_000 {
            let axis = Vector::new(next(), next(), next()).normalize_or(Vector::X);
            let kept = Pose::from_parts(
                crate::tangent::vector([next() * 10.0, next() * 10.0, next() * 10.0]),
                Rotation::from_axis_angle(axis, next() * std::f32::consts::PI),
            );
            // Turns and moves from 1e-9 to 1e-1 (rad, m), log-uniform.
            let scale = 10f32.powf(-9.0 + 8.0 * (next() * 0.5 + 0.5));
            let turn_axis = Vector::new(next(), next(), next()).normalize_or(Vector::Y);
            let moved = Pose::from_parts(
                kept.translation + Vector::new(next(), next(), next()) * scale,
                Rotation::from_axis_angle(turn_axis, next() * scale) * kept.rotation,
            );
            let reach = 10f32.powf(-2.0 + 3.7 * (next() * 0.5 + 0.5));
            let (motion, limit) = (0.0005 * (next() * 0.5 + 0.5), 0.0125);
            let q = QuietPose::new(&kept, reach);
            let now = QuietPose::new(&moved, reach);
            let measured = drift(&q.pose(), &now.pose(), q.reach()) + motion <= limit;
            if q.surely_within(&now, q.reach(), motion, limit) {
                told += 1;
                assert!(
                    measured,
                    "case {k}: the bound said within, the drift did not"
                );
            }
            if measured && scale * (1.0 + 2.0 * reach) < 0.1 * limit {
                small += 1;
                agreed += usize::from(q.surely_within(&now, q.reach(), motion, limit));
            }
        }
        assert!(told > 10_000, "the bound told only {told} of 40000");
        assert!(
            agreed * 10 >= small * 9,
            "{agreed} of {small} small moves told"
        );
    }
}
