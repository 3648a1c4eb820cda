//! One step of the friction law per contact manifold, at the end of avian's narrow phase: the
//! manifold's slip and the last solve's measurement in, its `friction` (the law's limit) and
//! `tangent_velocity` (the law's target, moving surfaces) out.
//!
//! avian's solver drives (v₂ − v₁) + `tangent_velocity` to zero at each point, so a surface
//! target t for v₂ − v₁ (the kernel's and rapier's convention) is written as −t. The slip the
//! law sees is the relative velocity of the touching material points, ġ = v₂ − v₁ + the
//! manifold's tangent velocity (what the app's hooks set, plus the `SurfaceVelocity`s).

use crate::dim::{self, Angular, basis, lift, local_normal, point_velocity, vector};
use crate::key::{ContactKey, Part};
use crate::pair_law::{PairLaws, Side, side};
use crate::plugin::StickSlipAvianConfig;
use crate::rolling::{Rolling, RollingBody, RollingContact};
use crate::store::ContactStore;
use avian::collision::narrow_phase::NarrowPhaseConfig;
use avian::dynamics::rigid_body::sleeping::SleepTimer;
use avian::math::Vector;
use avian::prelude::*;
use bevy::ecs::system::SystemParam;
use bevy::prelude::*;
use stickslip_bevy::{StickSlipFriction, StickSlipVibration, SurfaceVelocity};
use stickslip_core::contact::{ContactInput, step_contact};
use stickslip_core::law::{Coulomb, FrictionLaw, Law};

/// The friction coefficient per point, over the law's limit, of a contact held at its capacity
/// whose points did not all share the friction as the load asked (see `apply`).
const HEADROOM: f32 = 2.0;

/// The components of a collider stickslip reads.
type ColliderItem = (
    Option<&'static StickSlipFriction>,
    Option<&'static Friction>,
    Option<&'static StickSlipVibration>,
    Option<&'static SurfaceVelocity>,
    Option<&'static ColliderOf>,
    Option<&'static Rotation>,
);

/// The components of a body stickslip reads.
type BodyItem = (
    &'static RigidBody,
    Option<&'static LinearVelocity>,
    Option<&'static AngularVelocity>,
    Option<&'static ComputedMass>,
    Option<&'static Friction>,
    Option<&'static ComputedAngularInertia>,
);

/// What `apply` reads besides the contact graph.
#[derive(SystemParam)]
pub(crate) struct World<'w, 's> {
    colliders: Query<'w, 's, ColliderItem>,
    bodies: Query<'w, 's, BodyItem>,
    default_friction: Res<'w, DefaultFriction>,
    narrow_phase: Res<'w, NarrowPhaseConfig>,
    config: Res<'w, StickSlipAvianConfig>,
    time: Res<'w, Time>,
    substeps: Res<'w, SubstepCount>,
}

/// A body's motion at a contact.
#[derive(Clone, Copy, Default)]
struct Motion {
    linear: Vector,
    angular: Angular,
    inv_mass: f32,
    /// The largest inverse principal inertia, bounded from above (0 unless dynamic).
    inv_inertia: f32,
    /// Dynamic: a body the contact turns (a static or kinematic one's rolling arm is
    /// infinite).
    dynamic: bool,
}

impl World<'_, '_> {
    fn motion(&self, body: Option<Entity>) -> Motion {
        let Some((rb, v, w, m, _, i)) = body.and_then(|b| self.bodies.get(b).ok()) else {
            return Motion::default();
        };
        let dynamic = rb.is_dynamic();
        Motion {
            linear: v.map_or(Vector::ZERO, |v| v.0),
            angular: w.map_or(Angular::default(), |w| w.0),
            inv_mass: if dynamic {
                m.map_or(0.0, |m| m.inverse())
            } else {
                0.0
            },
            inv_inertia: i
                .filter(|_| dynamic)
                .map_or(0.0, dim::largest_inverse_inertia),
            dynamic,
        }
    }

    fn body_friction(&self, collider_of: Option<&ColliderOf>) -> Option<&Friction> {
        collider_of
            .and_then(|c| self.bodies.get(c.body).ok())
            .and_then(|(.., f, _)| f)
    }
}

/// Steps the law on every touching manifold of the pairs stickslip owns.
pub(crate) fn apply(
    mut graph: ResMut<ContactGraph>,
    mut store: ResMut<ContactStore>,
    mut laws: ResMut<PairLaws>,
    mut rolling: ResMut<Rolling>,
    mut timers: Query<&mut SleepTimer>,
    world: World,
) {
    let store = &mut *store;
    store.tick += 1;
    store.stepped.clear();
    let dt = world.time.delta_secs_f64();
    rolling.begin(dt);
    // Also rejects NaN.
    if dt.is_nan() || dt <= 0.0 {
        rolling.end();
        return;
    }
    let time = world.time.elapsed_secs_f64() - dt;
    let tick = store.tick;
    let default_friction = world.default_friction.0;
    for pair in graph.active_pairs_mut() {
        if !pair.generates_constraints() || !pair.is_touching() || pair.manifolds.is_empty() {
            continue;
        }
        let (Ok(c1), Ok(c2)) = (
            world.colliders.get(pair.collider1),
            world.colliders.get(pair.collider2),
        ) else {
            continue;
        };
        let (marked1, friction1, vib1, surface1, of1, rot1) = c1;
        let (marked2, friction2, vib2, surface2, of2, _) = c2;
        // The shared component is 3D; a 2D surface moves in the plane (z dropped).
        let surface = surface2.map_or(Vec3::ZERO, |s| s.0) - surface1.map_or(Vec3::ZERO, |s| s.0);
        let surface = vector(surface.to_array());
        let source = vib1.or(vib2).map(|v| &v.0);
        let sides = (
            side(
                pair.collider1,
                marked1,
                friction1,
                world.body_friction(of1),
                default_friction,
                &world.config.default_material,
            ),
            side(
                pair.collider2,
                marked2,
                friction2,
                world.body_friction(of2),
                default_friction,
                &world.config.default_material,
            ),
        );
        // A pair of two plain avian colliders whose friction the app's own hooks changed
        // (it is no longer the combination avian wrote) keeps the app's Coulomb friction.
        let apps = matches!(sides, (Side::Plain(a), Side::Plain(b))
            if pair.manifolds.iter().any(|m| m.friction != a.combine(b).dynamic_coefficient));
        let law = if apps {
            None
        } else {
            laws.law(sides.0, sides.1)
        };
        let driven = surface != Vector::ZERO || source.is_some();
        if law.is_none() && !driven {
            // avian's own Coulomb friction, untouched.
            continue;
        }
        let (m1, m2) = (world.motion(pair.body1), world.motion(pair.body2));
        if driven {
            // A moving or vibrating surface is never at rest: what it touches stays awake.
            for body in [pair.body1, pair.body2].into_iter().flatten() {
                if let Ok(mut t) = timers.get_mut(body) {
                    t.0 = 0.0;
                }
            }
        }
        // A surface or vibration on a pair of avian's own friction: Coulomb at its
        // coefficient, so that the vibration acts on it too.
        let coulomb;
        let law = match law {
            Some(l) => l,
            None => {
                coulomb = Law::Coulomb(Coulomb::clamped(pair.manifolds[0].friction as f64));
                &coulomb
            }
        };
        let manifolds = pair.manifolds.len();
        let rel = if vib1.is_some() { -1.0 } else { 1.0 };
        for (index, manifold) in pair.manifolds.iter_mut().enumerate() {
            if manifold.points.is_empty() {
                continue;
            }
            let n = manifold.normal;
            let key = ContactKey {
                collider1: pair.collider1,
                collider2: pair.collider2,
                part: Part::of(manifolds, local_normal(rot1, n)),
            };
            let points = manifold.points.len() as f32;
            let (r1, r2) = manifold
                .points
                .iter()
                .fold((Vector::ZERO, Vector::ZERO), |(a, b), p| {
                    (a + p.anchor1, b + p.anchor2)
                });
            let (r1, r2) = (r1 / points, r2 / points);
            // avian's tangent velocity of the touching points: the app's hooks' and the
            // surfaces' (−(v₂ − v₁) they ask for).
            let drive = dim::surface(manifold) + surface;
            let drive = drive - n * n.dot(drive);
            let v1 = point_velocity(m1.linear, m1.angular, r1);
            let v2 = point_velocity(m2.linear, m2.angular, r2);
            let basis = basis(n);
            let slip = basis.project(lift(v2 - v1 + drive).to_array());
            let record = store.records.entry(key).or_default();
            let warm: f32 = manifold
                .points
                .iter()
                .map(|p| p.warm_start_normal_impulse)
                .sum();
            let warm_start = if manifolds <= 4
                && world.narrow_phase.match_contacts
                && record.measured.normal_impulse > 0.0
            {
                (warm / record.measured.normal_impulse) as f64
            } else {
                1.0
            };
            // The last solve stayed inside the limit it had.
            let inside = f64::from(stickslip_core::contact::length(record.measured.mu))
                < (1.0 - stickslip_core::contact::SATURATION) * f64::from(record.state.limit);
            let out = step_contact(
                &mut record.state,
                &ContactInput::new(law, &basis, dt)
                    .with_solve(
                        record.measured.normal_force,
                        basis.project(record.measured.mu),
                        slip,
                    )
                    .with_source(source, rel)
                    .at_time(time)
                    .with_inv_mass((m1.inv_mass + m2.inv_mass) as f64)
                    .with_stiffness_time(world.config.stiffness_time)
                    .with_warm_start(warm_start),
            );
            record.tick = tick;
            record.slip = Vec3::from_array(basis.lift(slip));
            record.point = lift(manifold.points.iter().map(|p| p.point).sum::<Vector>() / points);
            record.normal = lift(n);
            // avian clamps each point at the coefficient times its own normal impulse. A held
            // box that its load tips forward carries less normal impulse at its back points
            // than their share of the friction: they sit at their clamp while the front ones
            // hold, and while avian's soft normal rows move the load between them (about a
            // second at 2 substeps) the clamped points let the contact slip by tens of
            // microns. So a contact the law holds at its capacity (formed, its last solve
            // inside the limit, no vibration) whose points did not all share the friction as
            // they liked gets HEADROOM times the limit per point until it stops holding: its
            // points share the friction as the load asks, and the kernel judges the whole
            // contact against the law's limit (a total that reaches it ends the hold, one
            // tick later than a point would have).
            record.headroom = out.holding
                && inside
                && record.state.forming == 0
                && source.is_none()
                && out.limit <= law.static_coefficient()
                && (record.headroom || record.measured.partly_clamped);
            manifold.friction = if record.headroom {
                record.state.limit * HEADROOM
            } else {
                record.state.limit
            };
            if slip == [0.0, 0.0] {
                start_inside_the_cone(manifold);
            }
            // The law's target is one for v₂ − v₁: avian's sign is the other.
            let target = drive - vector(basis.lift(out.target));
            dim::set_surface(manifold, target);
            store.stepped.insert((pair.contact_id.0, index), key);
        }
        if let Some(rotation) = laws.rotation(sides.0, sides.1) {
            // The manifold carrying the most points, with its last tick's normal force.
            let Some((index, m)) = pair
                .manifolds
                .iter()
                .enumerate()
                .max_by_key(|(_, m)| m.points.len())
            else {
                continue;
            };
            // The tick's mean (the sum over its substeps): a rolling contact's last substep
            // carries less than its share.
            let normal_force = store
                .stepped
                .get(&(pair.contact_id.0, index))
                .and_then(|k| store.records.get(k))
                .map_or(0.0, |r| r.tick_forces.normal_force);
            let points = m.points.len().max(1) as f32;
            let anchors = m
                .points
                .iter()
                .fold((Vector::ZERO, Vector::ZERO), |(a, b), p| {
                    (a + p.anchor1, b + p.anchor2)
                });
            let body = |entity, motion: Motion, anchor| RollingBody {
                entity,
                dynamic: motion.dynamic,
                angular: motion.angular,
                inv_inertia: motion.inv_inertia,
                anchor,
            };
            rolling.step_pair(
                (pair.collider1, pair.collider2),
                rotation,
                RollingContact {
                    points: &m.points,
                    normal: m.normal,
                    normal_force,
                },
                (
                    body(pair.body1, m1, anchors.0 / points),
                    body(pair.body2, m2, anchors.1 / points),
                ),
                world.substeps.0,
                time,
                world.config.stiffness_time,
            );
        }
    }
    rolling.end();
}

/// Scales the manifold's warm-start friction impulses into the friction cone of the limit
/// just written: their sum at most the limit times the points' warm-start normal impulses.
/// avian re-clamps a contact's accumulated friction impulse only while the contact's tangent
/// speed is not exactly zero (`tangent_part.rs` returns early otherwise): a warm start from a
/// larger limit (the law's static limit before a vibration lowered it) that stops the contact
/// exactly would hold it for ever, above the new limit. Only for contacts at exact rest (the
/// solver clamps the others itself, with this tick's normal impulses); the points keep their
/// shares (how the solver spread the friction over them).
fn start_inside_the_cone(manifold: &mut ContactManifold) {
    let (normal, tangent) = manifold.points.iter().fold((0.0, Vec2::ZERO), |(n, t), p| {
        (
            n + p.warm_start_normal_impulse.max(0.0),
            t + p.warm_start_tangent_impulse,
        )
    });
    let (most, length) = (manifold.friction * normal, tangent.length());
    if length > most {
        let scale = most / length;
        for point in manifold.points.iter_mut() {
            point.warm_start_tangent_impulse *= scale;
        }
    }
}
