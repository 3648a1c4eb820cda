//! The per-manifold work inside rapier's `modify_solver_contacts`.
//!
//! ## How the law maps onto rapier (per manifold, `FrictionModel::Simplified`)
//! rapier keeps one friction coefficient per manifold and, by default in 3D, solves one
//! friction constraint per manifold (plus twist). So stickslip keeps **one friction state per
//! manifold** (a contact patch), with the patch centroid as contact point, the summed normal
//! impulse as normal force and the manifold's friction impulse as friction force. Each step:
//!
//! 1. Measure from the previous solve (the manifold points carry it): normal force
//!    F_n = Σ impulse / dt, friction ratio μ⃗_meas = friction impulse / normal impulse of the last
//!    substep, and the slip ġ = v₂ − v₁ − (surface velocity of inner hooks) at the centroid.
//! 2. **Holding** (the solver's friction stayed below the limit it was given last step, any
//!    law but Regul): the rigid friction constraint is the c → ∞ limit of the law's elastic
//!    branch, so the state is read back (s⃗ = F_n μ⃗_meas, not broken away) instead of
//!    integrating the solver's tiny residual slip, and the solver gets a target
//!    tangent velocity pulling the contact back to its stick anchor plus the law's elastic
//!    displacement s⃗/(c F_n): sticking without creep.
//!    **Slipping** (the friction reached the limit: the solver let the contact slip): the law
//!    integrates the slip Δg⃗ = ġ dt (EP: exact/implicit, bounded for
//!    any c and dt) and the anchor follows.
//! 3. The solver's friction limit: holding, the law's capacity before it yields (EP:
//!    max(|μ⃗|, μ_ba); Phys: μ_ba; Coulomb: μ); slipping, the law's own coefficient |μ⃗| after
//!    the step (EP: its state, so a contact dragged across a surface feels the law's elastic
//!    loading and yielding, Popov's stick-slip included; Phys: μ_ve(|ġ|); Regul: μ(ġ)),
//!    scaled by the vibration source. The tangential stiffness uses a low-pass filtered mean
//!    normal force (`stiffness_time`), so a vibrating load changes the limit, not k_t.
//!
//! The law is realized through the solver's friction limit and target velocity, never as an
//! explicit spring force, so no stiffness c can destabilize the step.

use crate::contact_store::{ContactKey, ContactRecord};
use crate::modifier::StickSlip;
use crate::report::ContactReport;
use crate::tangent::TangentBasis;
use crate::vibration::{VibrationDirection, VibrationMode, VibrationSource};
use rapier3d::prelude::*;
use stickslip_core::law::{FrictionLaw, FrictionState, Law, Regime, StepInput};
use stickslip_core::sliding_curve::SlidingCurve;
use stickslip_core::vec2::{self, Vec2};

fn regime_code(r: Regime) -> u8 {
    match r {
        Regime::Sticking => 0,
        Regime::StickSlip => 1,
        Regime::Sliding => 2,
    }
}

/// Regime code of a contact whose inputs were not usable this step (see `apply`).
pub(crate) const REGIME_RESET: u8 = 254;

/// Beyond these a contact's inputs are garbage for an f32 solver, not physics: a force whose
/// friction share overflows f32, a slip faster than anything rapier integrates meaningfully.
const MAX_SANE_FORCE: f64 = 1e30;
const MAX_SANE_SPEED: f64 = 1e15;

fn regime_of(code: u8) -> Regime {
    match code {
        1 => Regime::StickSlip,
        2 => Regime::Sliding,
        _ => Regime::Sticking,
    }
}

/// Relative margin below the imposed limit within which the solver's friction counts as
/// saturated (the impulses are f32).
const SATURATION: f64 = 1e-3;

/// Normal and friction measurement of a manifold from the last solve.
struct Measured {
    /// Normal force over the step (N).
    normal_force: f64,
    /// Friction impulse over normal impulse of the last substep: μ⃗ with F_f(body 2) = −F_n μ⃗.
    mu: Vector,
}

fn measure(m: &ContactManifold, dt: f64) -> Measured {
    let (mut impulse, mut warm) = (0.0f64, 0.0f64);
    let mut friction = Vector::ZERO;
    for (i, p) in m.points.iter().enumerate() {
        impulse += p.data.impulse as f64;
        warm += p.data.warmstart_impulse as f64;
        // One friction constraint per group of 4 points stores its impulse on each point.
        if i % 4 == 0 {
            friction += p.data.warmstart_tangent_world;
        }
    }
    Measured {
        normal_force: if dt > 0.0 { impulse / dt } else { 0.0 },
        mu: if warm > 0.0 {
            friction / warm as f32
        } else {
            Vector::ZERO
        },
    }
}

fn centroid(contacts: &[SolverContact]) -> (Vector, Vector) {
    let k = contacts.len().max(1) as f32;
    let mut p = Vector::ZERO;
    let mut surface = Vector::ZERO;
    for c in contacts {
        p += (c.anchor1 + c.anchor2) * 0.5;
        surface += c.tangent_velocity;
    }
    (p / k, surface / k)
}

fn point_velocity(bodies: &RigidBodySet, h: Option<RigidBodyHandle>, p: Vector) -> Vector {
    h.and_then(|h| bodies.get(h))
        .map(|b| b.velocity_at_point(p))
        .unwrap_or(Vector::ZERO)
}

fn key(c1: ColliderHandle, c2: ColliderHandle, m: &ContactManifold) -> ContactKey {
    let features = m.points.first().map_or(0, |p| {
        ((p.fid1.0 as u64) << 32 | p.fid2.0 as u64)
            ^ ((m.subshape1 as u64) << 17)
            ^ ((m.subshape2 as u64) << 47)
    });
    ContactKey { c1, c2, features }
}

/// Elastic displacement of the law's spring, s⃗/k_t with k_t = c F_n (EP only).
fn elastic_displacement(law: &Law, force: Vector, f_n: f64) -> Vector {
    match law {
        Law::ElastoPlastic(l) if f_n > 0.0 => {
            // In f64: c·F_n may lie outside f32's range even when the displacement does not.
            let d = force.as_dvec3() / (l.c() * f_n);
            if d.is_finite() {
                d.as_vec3()
            } else {
                Vector::ZERO
            }
        }
        _ => Vector::ZERO,
    }
}

/// The vibration's effect on the limit: factor on the coefficient and the modulated normal
/// force the law sees.
struct Vibrated {
    normal_factor: f64,
}

impl<H: PhysicsHooks> PhysicsHooks for StickSlip<H> {
    fn filter_contact_pair(&self, context: &PairFilterContext) -> Option<SolverFlags> {
        self.inner.filter_contact_pair(context)
    }

    fn filter_intersection_pair(&self, context: &PairFilterContext) -> bool {
        self.inner.filter_intersection_pair(context)
    }

    fn modify_solver_contacts(&self, ctx: &mut ContactModificationContext) {
        let (c1, c2) = (ctx.collider1, ctx.collider2);
        let Some(rigid) = ctx.rigid() else {
            self.inner.modify_solver_contacts(ctx);
            return;
        };
        // A manifold without solver contacts and without a record (a pair inside the
        // prediction distance, not touching) has nothing for the law: no record is made
        // unless the wrapped hook keeps a value in its user_data.
        if rigid.solver_contacts.is_empty() && *rigid.user_data == 0 {
            self.inner.modify_solver_contacts(ctx);
            let Some(r) = ctx.rigid_mut() else { return };
            let inner_data = *r.user_data;
            if inner_data == 0 {
                return;
            }
            let key = key(c1, c2, r.manifold);
            let mut user_data = 0;
            self.store
                .with_record(&mut user_data, &key, self.clock.mark(), |rec, _, ours| {
                    rec.inner_user_data = inner_data;
                    *r.user_data = ours;
                });
            return;
        }
        let key = key(c1, c2, rigid.manifold);
        let mut user_data = *rigid.user_data;
        let step = self.clock.mark();
        // The manifold's user_data is ours; the inner hook sees its own value.
        self.store
            .with_record(&mut user_data, &key, step, |rec, _, ours| {
                if let Some(r) = ctx.rigid_mut() {
                    *r.user_data = rec.inner_user_data;
                }
                self.inner.modify_solver_contacts(ctx);
                if let Some(r) = ctx.rigid_mut() {
                    rec.inner_user_data = *r.user_data;
                    *r.user_data = ours;
                }
                self.apply(ctx, rec);
            });
    }
}

impl<H: PhysicsHooks> StickSlip<H> {
    fn apply(&self, ctx: &mut ContactModificationContext, rec: &mut ContactRecord) {
        let (c1, c2) = (ctx.collider1, ctx.collider2);
        let (bodies, colliders) = (ctx.bodies, ctx.colliders);
        let (rb1, rb2) = (ctx.rigid_body1, ctx.rigid_body2);
        let material = self
            .materials
            .get(c1)
            .or_else(|| self.materials.get(c2))
            .unwrap_or(&self.default_material);
        let source = self.vibrations.get(c1).or_else(|| self.vibrations.get(c2));
        let law = &material.law;
        let Some(m) = ctx.rigid_mut() else { return };
        let dt = self.clock.dt;
        if m.solver_contacts.is_empty() || !(dt > 0.0) {
            return;
        }
        let (Some(col1), Some(col2)) = (colliders.get(c1), colliders.get(c2)) else {
            return;
        };
        let basis = TangentBasis::new(*m.normal);
        let (p, surface) = centroid(m.solver_contacts);
        let slip_w = basis
            .tangential(point_velocity(bodies, rb2, p) - point_velocity(bodies, rb1, p) - surface);
        let slip: Vec2 = basis.project(slip_w);
        let speed = vec2::norm(slip);
        let meas = measure(m.manifold, dt);
        let f_n = meas.normal_force;
        // Non-finite or absurd inputs (a body given a NaN or 1e38 velocity, impulses that
        // overflowed) never enter the friction state: the contact is reset, held by the
        // law's static coefficient, and reported as reset.
        if !(speed <= MAX_SANE_SPEED
            && f_n.abs() <= MAX_SANE_FORCE
            && meas.mu.is_finite()
            && p.is_finite()
            && slip_w.is_finite())
        {
            rec.force = Vector::ZERO;
            rec.slide = 0.0;
            rec.anchored = false;
            rec.mean_normal_force = 0.0;
            rec.slip_speed = 0.0;
            rec.regime = REGIME_RESET;
            *m.friction = law.static_coefficient() as f32;
            rec.limit = *m.friction;
            return;
        }
        // Regul cannot stick: the solver never holds it.
        let regul = matches!(law, Law::Regularized(_));
        let holding;
        let t_mid = self.clock.time + 0.5 * dt;

        let mut limit;
        if !(f_n > 0.0 && f_n.is_finite()) {
            // No load: a new contact, or one that lost its load (flight, separation inside
            // the prediction distance). An unloaded spring relaxes (the law's state goes to
            // zero) and nothing of the old stick position survives: the contact re-anchors
            // where it lands and holds up to the static coefficient.
            rec.force = Vector::ZERO;
            rec.slide = 0.0;
            rec.anchored = false;
            // Like a new contact, a landing seeds its mean normal force (the law's stiffness
            // c·F̄) with its first load: an impact is as stiff as the seed's law, Eq. 4.
            rec.mean_normal_force = 0.0;
            holding = !regul;
            rec.regime = regime_code(Regime::Sticking);
            limit = match law {
                Law::Regularized(_) => law.sliding_coefficient(speed),
                _ => law.static_coefficient(),
            };
            if let Some(s) = source {
                limit *= static_factor(s, limit, None, t_mid);
            }
        } else {
            // Mean normal force for the tangential stiffness: filtered, seeded at first load.
            let f_mean = if rec.mean_normal_force > 0.0 {
                let tau = source.map_or(self.config.stiffness_time, |s| {
                    self.config.stiffness_time.max(5.0 / s.frequency())
                });
                let w = (dt / tau).min(1.0);
                rec.mean_normal_force as f64 + w * (f_n - rec.mean_normal_force as f64)
            } else {
                f_n
            };
            rec.mean_normal_force = f_mean as f32;
            let vib = source.map_or(Vibrated { normal_factor: 1.0 }, |s| {
                normal_modulation(s, f_n, t_mid)
            });
            let f_eff = f_n * vib.normal_factor;
            let measured = vec2::scale(basis.project(meas.mu), f_n);
            let input = |slip: Vec2| StepInput {
                slip,
                dt,
                normal_force: f_eff,
                stiffness_normal_force: f_mean,
            };
            // Stick or slip is the solver's verdict under the limit the law gave it last step:
            // a friction impulse below that limit means the rigid constraint held the contact
            // (the c → ∞ limit of the law's elastic branch: the state is what the constraint
            // carried, read back, and the contact has not broken away); at the limit the
            // contact slipped, and the law integrates the slip from its own state.
            let mu_meas = vec2::norm(basis.project(meas.mu));
            let saturated = rec.limit > 0.0 && mu_meas >= (1.0 - SATURATION) * rec.limit as f64;
            holding = !saturated && !regul;
            let mut state = if holding {
                FrictionState::with_force(measured)
            } else {
                FrictionState {
                    force: basis.project(rec.force),
                    slide: rec.slide as f64,
                }
            };
            let out = if holding {
                law.step(&mut state, &input([0.0; 2]))
            } else {
                // rapier moves the bodies with the velocity *after* this step's solve, so the
                // slip this step makes is ġ_{k+1} dt. While the slip accelerates (break-away),
                // extrapolate it, ġ_{k+1} ≈ ġ_k + (|ġ_k| − |ġ_{k−1}|) along ġ_k, at most doubled;
                // otherwise ġ_k: the law is then not one step behind the motion it resists.
                let growth = (speed - rec.slip_speed as f64).clamp(0.0, speed);
                let ahead = if speed > 0.0 {
                    1.0 + growth / speed
                } else {
                    1.0
                };
                law.step(&mut state, &input(vec2::scale(slip, dt * ahead)))
            };
            rec.force = basis.lift(state.force);
            rec.slide = state.slide as f32;
            rec.regime = regime_code(if holding && out.regime == Regime::Sliding {
                Regime::StickSlip
            } else {
                out.regime
            });
            // Holding: the law's capacity before it yields. Slipping: the law is resolved by
            // the step, so the solver applies exactly the law's force |μ⃗| F_n.
            let mu_law = if holding {
                out.limit
            } else {
                vec2::norm(out.mu)
            };
            limit = mu_law * vib.normal_factor;
            if let Some(s) = source {
                limit = in_plane_limit(s, limit, f_n, &basis, out.mu, slip, t_mid, holding, law);
            }
        }
        // Regul has no sticking: realized implicitly, the solver gets the full sliding level
        // and a target slip velocity equal to the law's creep speed under the load it carried,
        // ġ = ġ_t0 r⁻¹(|μ_meas|/μ_ve) along the load; at equilibrium that is exactly Regul.
        if let Law::Regularized(l) = law
            && f_n > 0.0
        {
            let mu_meas = basis.project(meas.mu);
            let ratio = vec2::norm(mu_meas);
            limit = l.curve().mu(speed);
            if let Some(dir) = vec2::normalize(mu_meas) {
                let creep = basis.lift(vec2::scale(dir, l.creep_speed(ratio, speed)));
                for c in m.solver_contacts.iter_mut() {
                    c.tangent_velocity += creep;
                }
            }
        }
        *m.friction = limit.max(0.0) as f32;
        rec.limit = *m.friction;
        rec.slip_speed = if holding { 0.0 } else { speed as f32 };

        // Stick anchors: correct drift while holding, follow the contact while slipping.
        let d_el = elastic_displacement(law, rec.force, f_n);
        let (pose1, pose2) = (col1.position(), col2.position());
        if holding && rec.anchored && self.config.anchor_gain > 0.0 {
            // A moving surface (conveyor hooks) carries collider 1's anchor along (an inverse
            // transform per holding contact and step only where a surface moves).
            let mut a1 = pose1.transform_point(rec.anchor1);
            if surface != Vector::ZERO {
                a1 += surface * dt as f32;
                rec.anchor1 = pose1.inverse_transform_point(a1);
            }
            let drift = basis.tangential(pose2.transform_point(rec.anchor2) - a1) - d_el;
            let v_corr = drift * (-(self.config.anchor_gain / dt) as f32);
            for c in m.solver_contacts.iter_mut() {
                c.tangent_velocity += v_corr;
            }
        } else {
            // Slipping: the anchors follow the contact. The first held step (after a slip,
            // or a landing: an unloaded contact drops its anchors) anchors where the contact
            // came to rest, with the elastic displacement of the state read back then, so
            // re-sticking does not kick the bodies.
            rec.anchor2 = pose2.inverse_transform_point(p);
            rec.anchor1 = pose1.inverse_transform_point(p - d_el);
            rec.anchored = holding;
        }
    }
}

/// Time-resolved normal vibration: F_n(t) = F̄ (1 + A/F̄ w)⁺.
fn normal_modulation(s: &VibrationSource, f_mean: f64, t: f64) -> Vibrated {
    let factor = match (s.direction(), s.mode()) {
        (VibrationDirection::Normal, VibrationMode::TimeResolved) => {
            (1.0 + s.force_amplitude(f_mean) / f_mean * s.signal(t)).max(0.0)
        }
        _ => 1.0,
    };
    Vibrated {
        normal_factor: factor,
    }
}

/// Static (holding) factor of a source before any load is known, or in averaged mode.
fn static_factor(s: &VibrationSource, mu0: f64, f_mean: Option<f64>, t: f64) -> f64 {
    let Some(f) = f_mean.filter(|f| *f > 0.0) else {
        return 1.0;
    };
    let ratio = s.force_amplitude(f) / f;
    if mu0 <= 0.0 {
        return 1.0;
    }
    let _ = t;
    match s.direction() {
        VibrationDirection::Normal => (1.0 - ratio).max(0.0),
        VibrationDirection::Tangential { .. } => ((mu0 - ratio) / mu0).max(0.0),
        VibrationDirection::Transverse { .. } => (mu0 * mu0 - ratio * ratio).max(0.0).sqrt() / mu0,
    }
}

/// The limit after in-plane vibration (time-resolved) or Popov averaging (averaged mode).
#[allow(clippy::too_many_arguments)]
fn in_plane_limit(
    s: &VibrationSource,
    limit: f64,
    f_n: f64,
    basis: &TangentBasis,
    mu_state: Vec2,
    slip: Vec2,
    t: f64,
    holding: bool,
    law: &Law,
) -> f64 {
    match s.mode() {
        VibrationMode::Averaged => {
            if holding {
                return limit * static_factor(s, limit, Some(f_n), t);
            }
            match s.direction() {
                VibrationDirection::Normal => {
                    let a_f = s.force_amplitude(f_n);
                    let alpha = a_f / f_n;
                    // Popov's averaged sliding friction μ̄ = μ_k (1 − α Ψ_w(β)) with the law's
                    // sliding coefficient at this speed: continuous with the static
                    // μ_k (1 − α) as the slip speed goes to 0 (Ψ_w(0) = 1).
                    let speed = vec2::norm(slip);
                    let mu0 = law.sliding_coefficient(speed).max(1e-12);
                    let k_t = s.tangential_stiffness().or(match law {
                        Law::ElastoPlastic(l) => Some(l.c() * f_n),
                        _ => None,
                    });
                    let psi = match k_t {
                        Some(k) if a_f > 0.0 => s.psi(k * speed / (mu0 * a_f * s.frequency())),
                        _ => 0.0,
                    };
                    mu0 * (1.0 - alpha * psi).max(0.0)
                }
                // In-plane: the oscillating force adds to whatever the contact carries, so a
                // slipping contact (at rest or slow, where its law state holds it elastically)
                // yields at the same reduced level as a held one (Eq. 6, 8). Popov gives no
                // closed form of the sliding friction for in-plane vibration; at high slip
                // speed this underestimates it (issue: superimposed vibration).
                _ => limit * static_factor(s, limit, Some(f_n), t),
            }
        }
        VibrationMode::TimeResolved => {
            let axis = match s.direction() {
                VibrationDirection::Normal => return limit,
                VibrationDirection::Tangential { axis }
                | VibrationDirection::Transverse { axis } => Vector::new(axis[0], axis[1], axis[2]),
            };
            let Some(e) = vec2::normalize(basis.project(axis)) else {
                return limit;
            };
            let a = vec2::scale(e, s.force_amplitude(f_n) * s.signal(t));
            let cap = limit * f_n;
            // Direction of the steady friction on body 2: against the state, else the slip.
            let d = vec2::normalize(vec2::scale(mu_state, -1.0))
                .or_else(|| vec2::normalize(vec2::scale(slip, -1.0)));
            let r = match d {
                Some(d) => {
                    let along = vec2::dot(a, d);
                    let across = vec2::norm(vec2::sub(a, vec2::scale(d, along)));
                    (cap * cap - across * across).max(0.0).sqrt() - along
                }
                None => (cap * cap - vec2::dot(a, a)).max(0.0).sqrt(),
            };
            (r / f_n).max(0.0)
        }
    }
}

/// The read-back of one manifold after the step.
pub(crate) fn report(
    m: &ContactManifold,
    rec: &ContactRecord,
    (c1, c2): (ColliderHandle, ColliderHandle),
    bodies: &RigidBodySet,
    _colliders: &ColliderSet,
    dt: f64,
) -> ContactReport {
    if rec.regime == REGIME_RESET {
        return reset_report(rec, c1, c2);
    }
    let meas = measure(m, dt);
    let n = m.data.normal;
    let basis = TangentBasis::new(n);
    let (p, surface) = centroid(&m.data.solver_contacts);
    let slip = basis.tangential(
        point_velocity(bodies, m.data.rigid_body2, p)
            - point_velocity(bodies, m.data.rigid_body1, p)
            - surface,
    );
    let friction = basis.tangential(meas.mu) * -(meas.normal_force as f32);
    let f_n = meas.normal_force;
    let report = ContactReport {
        collider1: c1,
        collider2: c2,
        point: p.to_array(),
        normal: n.to_array(),
        regime: regime_of(rec.regime),
        mu: if f_n > 0.0 {
            rec.force.length() as f64 / f_n
        } else {
            0.0
        },
        limit: m.data.friction as f64,
        normal_force: f_n,
        friction_force: friction.to_array(),
        slip_velocity: slip.to_array(),
        dissipated_power: (-(friction.dot(slip)) as f64).max(0.0),
        reset: false,
    };
    // Inputs that turned non-finite after the hook ran (the solve itself overflowed).
    let numbers = [
        report.mu,
        report.limit,
        report.normal_force,
        report.dissipated_power,
    ];
    let vectors = [
        report.point,
        report.normal,
        report.friction_force,
        report.slip_velocity,
    ];
    if numbers.iter().all(|x| x.is_finite()) && vectors.iter().flatten().all(|x| x.is_finite()) {
        report
    } else {
        reset_report(rec, c1, c2)
    }
}

/// The report of a contact whose inputs were not usable: zeros, flagged.
fn reset_report(rec: &ContactRecord, c1: ColliderHandle, c2: ColliderHandle) -> ContactReport {
    ContactReport {
        collider1: c1,
        collider2: c2,
        point: [0.0; 3],
        normal: [0.0; 3],
        regime: Regime::Sticking,
        mu: 0.0,
        limit: rec.limit as f64,
        normal_force: 0.0,
        friction_force: [0.0; 3],
        slip_velocity: [0.0; 3],
        dissipated_power: 0.0,
        reset: true,
    }
}
