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
use std::sync::atomic::Ordering;
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
        // The source moves its own collider's surface: the base of the other body oscillates
        // by −u relative to it, in the slip convention (body 2 relative to body 1) by ∓u.
        let rel = if self.vibrations.get(c1).is_some() {
            -1.0
        } else {
            1.0
        };
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
        if surface != Vector::ZERO && !self.moving_surfaces.load(Ordering::Relaxed) {
            self.moving_surfaces.store(true, Ordering::Relaxed);
        }
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
        // A friction direction the solver must take (compliant in-plane vibration), and a
        // target slip velocity (averaged in-plane vibration: the free drive velocity).
        let mut directed: Option<Vec2> = None;
        let mut averaged_target: Option<Vec2> = None;
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
                limit *= static_factor(s, limit, None);
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
            // Time-resolved in-plane vibration on a compliant law while slipping: the law
            // integrates the seed's spring force S = s + a (see `vibration`).
            let compliant = match (source, law) {
                (Some(s), Law::ElastoPlastic(l))
                    if s.mode() == VibrationMode::TimeResolved && s.has_in_plane() =>
                {
                    Some((s, l.c() * f_mean))
                }
                _ => None,
            };
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
            // A compliant contact under in-plane vibration cannot hold once the spring force
            // it carries, s + a(t), leaves the friction circle (Eq. 9): it slips now.
            let overloaded = compliant.is_some_and(|(s, _)| {
                let a = in_plane_force(s, f_mean, &basis, rel, t_mid);
                vec2::norm(vec2::add(measured, a)) > law.static_coefficient() * f_eff
            });
            holding = !saturated && !regul && !overloaded;
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
                let g = vec2::scale(slip, dt * ahead);
                match compliant {
                    Some((s, k_t)) if k_t > 0.0 && k_t.is_finite() => {
                        let t0 = self.clock.time;
                        let a0 = in_plane_force(s, f_mean, &basis, rel, t0);
                        let a1 = in_plane_force(s, f_mean, &basis, rel, t0 + dt);
                        state.force = vec2::add(state.force, a0);
                        let g = vec2::add(g, vec2::scale(vec2::sub(a1, a0), 1.0 / k_t));
                        let out = law.step(&mut state, &input(g));
                        state.force = vec2::sub(state.force, a1);
                        out
                    }
                    _ => law.step(&mut state, &input(g)),
                }
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
            if compliant.is_some() && !holding {
                // The bodies feel the elastic part s of the spring force, exactly.
                limit = vec2::norm(state.force) / f_n;
                if let Some(dir) = vec2::normalize(state.force) {
                    let along = vec2::normalize(slip).map_or(0.0, |e| vec2::dot(e, dir));
                    if along < ALIGNED {
                        directed = Some(dir);
                    }
                }
            } else if let Some(s) = source {
                let (l, target) = in_plane_limit(
                    s, limit, f_n, f_mean, rel, &basis, out.mu, slip, t_mid, holding, law,
                );
                limit = l;
                averaged_target = target;
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
        if let Some(dir) = directed {
            // Saturate the solver along −ŝ: a target relative velocity far beyond what one
            // step's friction impulse |s| dt can reach, so the friction is exactly −s.
            let inv = inv_mass(bodies, rb1) + inv_mass(bodies, rb2);
            let reach = DIRECT_MARGIN * limit * f_n * dt * inv + speed;
            let v = basis.lift(vec2::sub(slip, vec2::scale(dir, reach)));
            if v.is_finite() {
                for c in m.solver_contacts.iter_mut() {
                    c.tangent_velocity += v;
                }
            }
        }
        if let Some(target) = averaged_target {
            let v = basis.lift(target);
            if v.is_finite() {
                for c in m.solver_contacts.iter_mut() {
                    c.tangent_velocity += v;
                }
            }
        }
        rec.slip_speed = if holding { 0.0 } else { speed as f32 };

        // Drift of a hold: the slip of the touching material points since the contact stuck
        // (integrated from ġ at the contact point, so rolling adds none), corrected towards
        // the law's elastic displacement through the solver's target velocity.
        let d_el = elastic_displacement(law, rec.force, f_n);
        if holding && rec.anchored && self.config.anchor_gain > 0.0 {
            let drift = basis.tangential(rec.anchor1 + slip_w * dt as f32);
            rec.anchor1 = drift;
            let v_corr = (drift - d_el) * (-(self.config.anchor_gain / dt) as f32);
            for c in m.solver_contacts.iter_mut() {
                c.tangent_velocity += v_corr;
            }
        } else {
            rec.anchor1 = d_el;
            rec.anchored = holding;
        }
        let _ = (col1, col2);
    }
}

/// Relative margin by which a directed friction's target velocity outruns what the step's
/// friction impulse can reach (covers the rotational part of the effective mass).
const DIRECT_MARGIN: f64 = 1e3;
/// Cosine between the spring force and the slip above which the solver's own direction
/// (against the slip) is the law's.
const ALIGNED: f64 = 0.999;

fn inv_mass(bodies: &RigidBodySet, h: Option<RigidBodyHandle>) -> f64 {
    h.and_then(|h| bodies.get(h))
        .filter(|b| b.is_dynamic())
        .map_or(0.0, |b| {
            let m = b.mass() as f64;
            if m > 0.0 { 1.0 / m } else { 0.0 }
        })
}

/// Time-resolved normal vibration: F_n(t) = F̄ (1 + A/F̄ w)⁺.
fn normal_modulation(s: &VibrationSource, f_mean: f64, t: f64) -> Vibrated {
    let factor = match (s.normal(), s.mode()) {
        (Some(c), VibrationMode::TimeResolved) => {
            (1.0 + c.amplitude().force(f_mean) / f_mean * s.component_signal(c, t)).max(0.0)
        }
        _ => 1.0,
    };
    Vibrated {
        normal_factor: factor,
    }
}

/// The in-plane part a⃗(t) = Σ ± A_i w_i ê_i of the contact spring's force (N), in the slip
/// convention (`rel` = −1 when the source is on collider 1).
fn in_plane_force(
    s: &VibrationSource,
    f_mean: f64,
    basis: &TangentBasis,
    rel: f64,
    t: f64,
) -> Vec2 {
    let mut a = [0.0; 2];
    for c in s.components() {
        let Some(axis) = c.direction().axis() else {
            continue;
        };
        let Some(e) = vec2::normalize(basis.project(Vector::new(axis[0], axis[1], axis[2]))) else {
            continue;
        };
        let w = rel * c.amplitude().force(f_mean) * s.component_signal(c, t);
        a = vec2::add(a, vec2::scale(e, w));
    }
    a
}

/// Static (holding) factor of a source before any load is known, or in averaged mode
/// without a table: Eq. 4 on the normal component, then Eq. 8 and Eq. 6 on what is left (each
/// exact alone).
fn static_factor(s: &VibrationSource, mu0: f64, f_mean: Option<f64>) -> f64 {
    let Some(f) = f_mean.filter(|f| *f > 0.0) else {
        return 1.0;
    };
    if mu0 <= 0.0 {
        return 1.0;
    }
    let (mut z, mut x, mut y) = (0.0f64, 0.0f64, 0.0f64);
    for c in s.components() {
        let ratio = c.amplitude().force(f) / f;
        match c.direction() {
            VibrationDirection::Normal => z = ratio,
            VibrationDirection::Tangential { .. } => x = ratio,
            VibrationDirection::Transverse { .. } => y = ratio,
        }
    }
    let cap = mu0 * (1.0 - z).max(0.0);
    let cap = if y > 0.0 {
        (cap * cap - y * y).max(0.0).sqrt()
    } else {
        cap
    };
    ((cap - x) / mu0).max(0.0)
}

/// The limit after in-plane vibration (time-resolved, rigid) or Popov averaging (averaged
/// mode), and the target slip velocity of an averaged in-plane source.
#[allow(clippy::too_many_arguments)]
fn in_plane_limit(
    s: &VibrationSource,
    limit: f64,
    f_n: f64,
    f_mean: f64,
    rel: f64,
    basis: &TangentBasis,
    mu_state: Vec2,
    slip: Vec2,
    t: f64,
    holding: bool,
    law: &Law,
) -> (f64, Option<Vec2>) {
    match s.mode() {
        VibrationMode::Averaged if s.has_in_plane() => {
            averaged_in_plane(s, limit, f_mean, rel, basis, mu_state, slip, holding, law)
        }
        VibrationMode::Averaged => {
            if holding {
                return (limit * static_factor(s, limit, Some(f_n)), None);
            }
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
            (mu0 * (1.0 - alpha * psi).max(0.0), None)
        }
        VibrationMode::TimeResolved => {
            if !s.has_in_plane() {
                return (limit, None);
            }
            let a = in_plane_force(s, f_n, basis, rel, t);
            let cap = limit * f_n;
            // Direction of the steady friction on body 2: against the state, else the slip.
            // It carries f⃗ = r d̂ with the spring force s⃗ = −f⃗: |−r d̂ + a⃗| ≤ cap.
            let d = vec2::normalize(vec2::scale(mu_state, -1.0))
                .or_else(|| vec2::normalize(vec2::scale(slip, -1.0)));
            let r = match d {
                Some(d) => {
                    let along = vec2::dot(a, d);
                    let across = vec2::norm(vec2::sub(a, vec2::scale(d, along)));
                    (cap * cap - across * across).max(0.0).sqrt() + along
                }
                None => (cap * cap - vec2::dot(a, a)).max(0.0).sqrt(),
            };
            ((r / f_n).max(0.0), None)
        }
    }
}

/// Averaged in-plane (and superimposed) vibration from the compliant theory's table: the
/// limit |μ̄(u)| and the target slip velocity v_d x̂ (see `vibration`).
#[allow(clippy::too_many_arguments)]
fn averaged_in_plane(
    s: &VibrationSource,
    limit: f64,
    f_mean: f64,
    rel: f64,
    basis: &TangentBasis,
    mu_state: Vec2,
    slip: Vec2,
    holding: bool,
    law: &Law,
) -> (f64, Option<Vec2>) {
    let mu0 = law.static_coefficient();
    let Some(table) = s.drive_table(mu0, f_mean) else {
        return (limit * static_factor(s, limit, Some(f_mean)), None);
    };
    // The theory's x̂ in the slip convention: the other body's base moves by +A w along it.
    let tangential = s.components().iter().find_map(|c| match c.direction() {
        VibrationDirection::Tangential { axis } => Some(axis),
        _ => None,
    });
    let x = match tangential {
        Some(axis) => vec2::normalize(basis.project(Vector::new(axis[0], axis[1], axis[2])))
            .map(|e| vec2::scale(e, rel)),
        None => vec2::normalize(slip).or_else(|| vec2::normalize(mu_state)),
    };
    let Some(x) = x else {
        return (table.upper.abs(), None);
    };
    // u = v k_t / (μ0 F̄ f); without a stiffness the rigid limit (u = ±∞ once moving).
    let k_t = s.tangential_stiffness().or(match law {
        Law::ElastoPlastic(l) => Some(l.c() * f_mean),
        _ => None,
    });
    let unit = k_t.map(|k| mu0 * f_mean * s.frequency() / k);
    let mu = if holding {
        let load = vec2::dot(mu_state, x);
        if load > 0.0 {
            table.upper
        } else if load < 0.0 {
            table.lower
        } else if table.upper < 0.0 {
            table.upper
        } else if table.lower > 0.0 {
            table.lower
        } else {
            table.upper
        }
    } else {
        let v = vec2::dot(slip, x);
        match unit {
            Some(unit) => table.eval(v / unit),
            None if v == 0.0 => table.upper,
            None => table.eval(v.signum() * f64::INFINITY),
        }
    };
    let target = match unit {
        Some(unit) if table.drive != 0.0 => Some(vec2::scale(x, table.drive * unit)),
        _ => None,
    };
    (mu.abs(), target)
}

/// The world-space centroid of a manifold's solver contacts after the step, and their mean
/// target velocity. After the hook, rapier re-expresses a dynamic body's solver anchors in
/// that body's frame, so the anchors are not world points any more; the manifold's local
/// points and the colliders' poses are.
fn world_centroid(
    m: &ContactManifold,
    colliders: &ColliderSet,
    (c1, c2): (ColliderHandle, ColliderHandle),
) -> Option<(Vector, Vector)> {
    let pose = |h: ColliderHandle, sub: Option<&Pose>| {
        let at = *colliders.get(h)?.position();
        Some(sub.map_or(at, |s| at * *s))
    };
    let (pos1, pos2) = (pose(c1, m.subshape_pos1())?, pose(c2, m.subshape_pos2())?);
    let contacts = &m.data.solver_contacts;
    let (mut p, mut surface) = (Vector::ZERO, Vector::ZERO);
    for c in contacts {
        let point = m.points.get(c.contact_indices()[0] as usize)?;
        p += (pos1 * point.local_p1 + pos2 * point.local_p2) * 0.5;
        surface += c.tangent_velocity;
    }
    let k = contacts.len().max(1) as f32;
    Some((p / k, surface / k))
}

/// The read-back of one manifold after the step (`moving_surfaces`: whether the wrapped hook
/// gives surfaces velocities, see `StickSlip::moving_surfaces`).
pub(crate) fn report(
    m: &ContactManifold,
    rec: &ContactRecord,
    (c1, c2): (ColliderHandle, ColliderHandle),
    bodies: &RigidBodySet,
    colliders: &ColliderSet,
    dt: f64,
    moving_surfaces: bool,
) -> ContactReport {
    if rec.regime == REGIME_RESET {
        return reset_report(rec, c1, c2);
    }
    let Some((p, targets)) = world_centroid(m, colliders, (c1, c2)) else {
        return reset_report(rec, c1, c2);
    };
    // The target velocities hold stickslip's own (anchor correction, Regul's creep,
    // vibration drive) besides a wrapped hook's surface velocity; without such a hook they
    // are not a surface's motion at all.
    let surface = if moving_surfaces {
        targets
    } else {
        Vector::ZERO
    };
    let meas = measure(m, dt);
    let n = m.data.normal;
    let basis = TangentBasis::new(n);
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
