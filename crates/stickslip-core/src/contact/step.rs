//! The per-manifold step: a pure function from what the last solve left at a contact patch
//! (normal force, measured friction, the slip of the touching points) and the contact's
//! friction state to what the solver gets next (a friction limit and a target tangent
//! velocity) and the updated state. It knows no engine: an adapter (stickslip-rapier's
//! `PhysicsHooks` impl) only gathers these inputs and writes the outputs.
//!
//! ## How sticking is realized
//! rapier solves one friction constraint per manifold (`FrictionModel::Simplified`): a rigid
//! constraint that drives the relative tangential velocity of the touching points to a target
//! (0 unless a surface moves) with an impulse bounded by limit × normal impulse. stickslip keeps
//! one friction state per manifold (a contact patch) and, each step:
//!
//! 1. **Hold or slip** is the solver's verdict under the limit the law gave it last step:
//!    friction below that limit means the rigid constraint held the contact — the c → ∞ limit
//!    of the law's elastic branch, so the state is the force the constraint carried, read back
//!    (s⃗ = F_n μ⃗_meas); friction at the limit means the contact slipped, and the law integrates
//!    the slip Δg⃗ = ġ dt of the **touching material points**, ġ = v₂ − v₁ at the contact point
//!    (EP: exactly, bounded for any c and dt).
//! 2. **The limit**: holding, the law's capacity before it yields (EP: max(|μ⃗|, μ_ba); Phys:
//!    μ_ba; Coulomb: μ) — also for a contact whose solver friction touched the limit while the
//!    law still calls it sticking (a memoryless law below its stick speed); slipping, the
//!    law's own coefficient after the step (EP: its state, so a dragged contact feels the law's
//!    elastic loading and yielding; Phys: μ_ve(|ġ|); Regul: μ(ġ)); then scaled by the
//!    vibration source (`crate::vibration_limit`).
//! 3. **The target velocity**: none while holding. Only the law or a source that *drives*
//!    motion sets one: Regul's creep ġ_t0 r⁻¹(|μ_meas|/μ_ve) along the load, the averaged
//!    drive velocity of in-plane vibration, a directed friction under compliant in-plane
//!    vibration.
//!
//! **Why a hold cannot pump energy.** A holding contact gives the solver a friction row with
//! target velocity 0 and a bounded impulse: each impulse of that row opposes the relative
//! tangential velocity it acts on (projected Gauss–Seidel on a row with zero right-hand side
//! only removes kinetic energy of the relative motion), so the row is dissipative whatever the
//! other constraints do. Nothing remembers a position: a body that rolls without slipping has
//! ġ = 0 at the contact, so neither the state nor the solver's target changes, and a stack
//! at rest stays at rest as under plain rapier.
//!
//! **Contact forming.** For the two steps after a solve that started cold — a new contact or a
//! landing (no warm start), a contact the kernel first meets already loaded (the engine formed
//! it without the adapter), or a clustered mesh patch whose points rapier re-picked while the
//! contact held (warm-started with < 90 % of the last normal impulse) — the contact holds at
//! its capacity whatever the solver did: that solve built the normal force up while friction
//! was capped by the part built so far, and the next stops the slip that let through. Plain
//! rapier lets a box put down on a slope slip 10–100 µm there; an EP law with g_ba of a few
//! µm would take it for break-away and, with μ_k < μ_s, slide off (`crates/stickslip-fixtures/tests/ordinary_grounds.rs`).
//!
//! **A load that jumps.** The first solve under a load that jumped starts from the last
//! solve's friction and touches the limit before it converges; the solves after it brake the
//! slip that let through, at the limit. A contact that held gives at its capacity while that
//! slip slows (see `gives`), reported stick-slip: a box on a slope jumped to 0.95 of
//! break-away holds as plain rapier's does, where the law took the slip for break-away and,
//! with μ_k < μ_s, slid off (`crates/stickslip-fixtures/tests/rapier_load_jump.rs`). A load above the capacity makes
//! the slip grow, and the law takes it.
//!
//! **Tried and dropped** (measured in `tests/ordinary_*.rs`): stick anchors — material points
//! fixed in each collider at the moment a contact stuck, their separation corrected through
//! the target velocity. A rolling body's material points leave the contact (after a quarter
//! turn the "drift" is 0.57 r): balls spun in place at 9× their rolling rate. Integrating the
//! drift from ġ at the contact instead fixed rolling, but any position correction through the
//! friction target is a bias velocity in friction, and coupled corrections pumped a crossed
//! plank tower (every plank > 1 mm, 58 of 60 > 1 cm in 10 s on a floor tilted to 0.1, where
//! plain rapier moves one plank by 1 mm), at gains from 0.05 to 0.5; rapier 0.36 itself keeps
//! friction out of its bias pass for the same reason. Without correction, rapier's rigid
//! friction row holds a loaded box as tightly as the law's elastic range (an incline at 0.95
//! of break-away: −4.7 µm in 10 s against g_ba = 50 µm), and the stack stands.

use super::state::{ContactState, REGIME_NONE, REGIME_RESET};
use super::tangent::{TangentBasis, length};
use super::vibration::{VibrationMode, VibrationSource};
use super::vibration_limit::{in_plane_force, in_plane_limit, normal_factor, static_factor};
use crate::law::{FrictionLaw, FrictionState, Law, Regime, StepInput};
use crate::vec2::{self, Vec2};

/// Relative margin below the imposed limit within which the solver's friction counts as
/// saturated (the impulses are f32).
#[doc(hidden)]
pub const SATURATION: f64 = 1e-3;

/// Beyond these a contact's inputs are garbage for an f32 solver, not physics: a force whose
/// friction share overflows f32, a slip faster than anything rapier integrates meaningfully.
const MAX_SANE_FORCE: f64 = 1e30;
/// The fastest slip (m/s) the kernel takes for physics: beyond it, it resets the contact.
pub const MAX_SANE_SPEED: f64 = 1e15;

/// A solve warm-started with less than this share of the last solve's normal impulse starts
/// cold: the contact forms again.
const WARM: f64 = 0.9;
/// Steps a contact takes to form after a cold solve: the cold one, and the one that stops
/// the slip it let through.
const FORMING_STEPS: u8 = 2;

/// `ContactState::forming` of a contact giving under a jump in load (see `step_contact`).
#[doc(hidden)]
pub const GIVING: u8 = 3;
/// Share of the limit below which the friction a held contact carried makes a saturated
/// solve after it a jump in load (see `step_contact`).
const JUMP_SHARE: f64 = 0.9;
/// Margin on the slip one step of the limit's impulse gives the bodies' masses (their
/// rotation makes the contact's effective mass smaller).
const GIVE_MARGIN: f64 = 2.0;

/// Relative margin by which a directed friction's target velocity outruns what the step's
/// friction impulse can reach (covers the rotational part of the effective mass).
const DIRECT_MARGIN: f64 = 1e3;
/// Cosine between the spring force and the slip above which the solver's own direction
/// (against the slip) is the law's.
const ALIGNED: f64 = 0.999;

/// What the last solve left at a contact patch, and what governs it.
///
/// Built with [`ContactInput::new`] and the `with_*` methods (the type grows with the kernel,
/// so it has no public literal); the fields can be read.
#[derive(Debug, Clone, Copy)]
#[non_exhaustive]
pub struct ContactInput<'a> {
    /// The contact's friction law.
    pub law: &'a Law,
    /// The vibration source of either collider.
    pub source: Option<&'a VibrationSource>,
    /// −1 when the source is on collider 1 (its surface moves the other body's base by −u in
    /// the slip convention), +1 otherwise.
    pub rel: f64,
    /// The contact's tangent plane (for the source's axes).
    pub basis: &'a TangentBasis,
    /// Normal force over the last step (N).
    pub normal_force: f64,
    /// Measured friction over normal impulse of the last solve, μ⃗ with F_f(body 2) = −F_n μ⃗,
    /// in the tangent plane.
    pub measured_mu: Vec2,
    /// Slip velocity of the touching points, ġ = v₂ − v₁ − surface, in the tangent plane (m/s).
    pub slip: Vec2,
    /// Step length (s), > 0.
    pub dt: f64,
    /// Time at the start of the step (s).
    pub time: f64,
    /// Sum of the two bodies' inverse masses (1/kg): how far one step's friction impulse
    /// reaches, for a directed friction.
    pub inv_mass: f64,
    /// Averaging time of the mean normal force (s, `StickSlipConfig::stiffness_time`).
    pub stiffness_time: f64,
    /// Share of the last solve's normal impulse the solver starts this step with (1 unless
    /// rapier re-picked the points of a clustered patch).
    pub warm_start: f64,
}

impl<'a> ContactInput<'a> {
    /// A contact governed by `law` in the tangent plane `basis`, stepped by `dt` seconds;
    /// before any `with_*`: no load, no slip, no vibration source, bodies of infinite mass,
    /// time 0, the default averaging time of the mean normal force (1 s) and a full warm start.
    #[inline]
    pub fn new(law: &'a Law, basis: &'a TangentBasis, dt: f64) -> Self {
        Self {
            law,
            source: None,
            rel: 1.0,
            basis,
            normal_force: 0.0,
            measured_mu: [0.0; 2],
            slip: [0.0; 2],
            dt,
            time: 0.0,
            inv_mass: 0.0,
            stiffness_time: 1.0,
            warm_start: 1.0,
        }
    }

    /// What the last solve left: its normal force (N), its friction over normal impulse μ⃗
    /// and the touching points' slip velocity (m/s), both in the tangent plane (see the
    /// fields).
    #[inline]
    pub fn with_solve(mut self, normal_force: f64, measured_mu: Vec2, slip: Vec2) -> Self {
        self.normal_force = normal_force;
        self.measured_mu = measured_mu;
        self.slip = slip;
        self
    }

    /// The vibration source of either collider, with `rel` = −1 when it is on collider 1
    /// and +1 otherwise.
    #[inline]
    pub fn with_source(mut self, source: Option<&'a VibrationSource>, rel: f64) -> Self {
        self.source = source;
        self.rel = rel;
        self
    }

    /// The time at the start of the step (s).
    #[inline]
    pub fn at_time(mut self, time: f64) -> Self {
        self.time = time;
        self
    }

    /// The sum of the two bodies' inverse masses (1/kg).
    #[inline]
    pub fn with_inv_mass(mut self, inv_mass: f64) -> Self {
        self.inv_mass = inv_mass;
        self
    }

    /// The averaging time of the mean normal force (s).
    #[inline]
    pub fn with_stiffness_time(mut self, stiffness_time: f64) -> Self {
        self.stiffness_time = stiffness_time;
        self
    }

    /// The share of the last solve's normal impulse the solver starts this step with.
    #[inline]
    pub fn with_warm_start(mut self, warm_start: f64) -> Self {
        self.warm_start = warm_start;
        self
    }
}

/// What the solver gets for the next step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactOutput {
    /// Friction coefficient limit (≥ 0).
    pub limit: f64,
    /// Target relative tangential velocity to add (m/s, tangent plane), from the law or the
    /// vibration source only; zero while holding.
    pub target: Vec2,
    /// Whether the contact holds (the solver's rigid friction row is the law's sticking).
    pub holding: bool,
}

/// The slip the law integrates this step. rapier moves the bodies with the velocity *after*
/// this step's solve, so the slip this step makes is ġ_{k+1} dt. While the slip accelerates
/// (break-away), extrapolate it, ġ_{k+1} ≈ ġ_k + (|ġ_k| − |ġ_{k−1}|) along ġ_k, at most
/// doubled; otherwise ġ_k: the law is then not one step behind the motion it resists.
fn slip_ahead(rec: &ContactState, slip: Vec2, dt: f64) -> Vec2 {
    let speed = vec2::norm(slip);
    let growth = (speed - rec.slip_speed as f64).clamp(0.0, speed);
    let ahead = if speed > 0.0 {
        1.0 + growth / speed
    } else {
        1.0
    };
    vec2::scale(slip, dt * ahead)
}

/// The fastest slip one step of the limit's impulse brakes (with a margin for the bodies'
/// rotation): a slip the solver is braking, not one the law must take.
fn one_step_slip(rec: &ContactState, input: &ContactInput) -> f64 {
    let f_n = input.normal_force.min(rec.mean_normal_force as f64);
    GIVE_MARGIN * rec.limit as f64 * f_n * input.dt * input.inv_mass
}

/// Whether a contact gives at its capacity this step instead of yielding: its solve
/// saturated under a load that jumped, and the slip is the solver braking its own lag.
///
/// The first solve under a new load starts from the last one's friction and touches the
/// limit before it has converged; the bodies keep the velocity that let through, and the
/// solves after it brake that slip at the limit (plain rapier's box slips 0.3–0.5 mm after a
/// jump to 0.95 of break-away at 60 Hz, then holds: `crates/stickslip-fixtures/tests/rapier_load_jump.rs`). An elastic
/// law with g_ba of microns, or a rigid one, would take that slip for break-away and, with
/// μ_k < μ_s, slide off. A load above the capacity makes the slip grow instead. So a contact
/// the law holds (sticking) gives while its slip
/// - saturates the solve, is faster than nothing and no faster than one step of the limit's
///   impulse moves the bodies (an impact's slip is the law's);
/// - started from a hold that carried well inside the limit under a normal force that did
///   not drop (a load rising over steps is resolved by the solver as it comes; an unloading
///   contact saturates without any jump), or shrinks from the last step's (a slip the law's
///   elastic range took at first, or a give going on).
fn gives(rec: &ContactState, input: &ContactInput, saturated: bool, speed: f64) -> bool {
    let limit = rec.limit as f64;
    let f_n = input.normal_force;
    if !(saturated && speed > 0.0 && speed <= one_step_slip(rec, input)) {
        return false;
    }
    let shrinking = speed < rec.slip_speed as f64;
    if rec.forming == GIVING {
        shrinking
    } else if rec.regime != Regime::Sticking.code() {
        false
    } else if rec.slip_speed == 0.0 {
        // The friction it carried was well inside the limit, under a normal force that did
        // not drop (a contact unloading, lifting off, saturates without any jump).
        (length(rec.force) as f64) < JUMP_SHARE * limit * f_n
            && f_n >= JUMP_SHARE * rec.mean_normal_force as f64
    } else {
        shrinking
    }
}

/// Whether [`step_contact`] reads the slip (and the bodies' inverse mass) of this contact:
/// not for a contact whose law sticks, that carries a load and whose last solve stayed below
/// the limit, with no vibration source — it is held, whatever it slips. An adapter may then
/// pass a zero slip and skip finding it.
pub fn slip_matters(
    rec: &ContactState,
    law: &Law,
    source: Option<&VibrationSource>,
    normal_force: f64,
    measured_mu: Vec2,
) -> bool {
    let mu_meas = vec2::norm(measured_mu);
    let reached = rec.limit > 0.0 && mu_meas >= (1.0 - SATURATION) * rec.limit as f64;
    !(source.is_none()
        && law.can_stick()
        && normal_force > 0.0
        && normal_force <= MAX_SANE_FORCE
        && mu_meas.is_finite()
        && !reached)
}

/// One step of one contact patch: updates `rec` and returns what the solver gets.
pub fn step_contact(rec: &mut ContactState, input: &ContactInput) -> ContactOutput {
    let ContactInput {
        law,
        source,
        rel,
        basis,
        normal_force: f_n,
        measured_mu,
        slip,
        dt,
        time,
        inv_mass,
        stiffness_time,
        warm_start: _,
    } = *input;
    let speed = vec2::norm(slip);
    let mu_meas = vec2::norm(measured_mu);
    // Non-finite or absurd inputs (a body given a NaN or 1e38 velocity, impulses that
    // overflowed) never enter the friction state: the contact is reset, held by the law's
    // static coefficient, and reported as reset.
    if !(speed <= MAX_SANE_SPEED && f_n.abs() <= MAX_SANE_FORCE && mu_meas.is_finite()) {
        *rec = ContactState {
            regime: REGIME_RESET,
            limit: law.static_coefficient() as f32,
            ..ContactState::default()
        };
        return ContactOutput {
            limit: law.static_coefficient(),
            target: [0.0; 2],
            holding: false,
        };
    }
    let can_stick = law.can_stick();
    let t_mid = time + 0.5 * dt;
    let mut target = [0.0; 2];
    let holding;
    let mut limit;
    if !(f_n > 0.0) {
        // No load: a new contact, or one that lost its load (flight, separation inside the
        // prediction distance). An unloaded spring relaxes (the law's state goes to zero);
        // like a new contact, a landing seeds its mean normal force (the stiffness c·F̄) with
        // its first load, so an impact is as stiff as the seed's law, Eq. 4.
        rec.force = [0.0; 3];
        rec.slide = 0.0;
        rec.mean_normal_force = 0.0;
        // The coming solve builds the normal force from nothing.
        rec.forming = FORMING_STEPS;
        holding = can_stick;
        rec.regime = Regime::Sticking.code();
        limit = if can_stick {
            law.static_coefficient()
        } else {
            law.sliding_coefficient(speed)
        };
        if let Some(s) = source {
            limit *= static_factor(s, limit, None);
        }
    } else {
        // The two steps after a solve that started cold — a new contact's or a landing's first,
        // or one that rapier warm-started with little of the last solve's normal impulse (a
        // clustered patch of a mesh whose points it re-picked) while the contact held: that solve built the normal
        // force up while friction was capped by the part built so far, and the next stops the
        // slip that let through. A slip there is the contact forming, not the law yielding:
        // plain rapier slips the same (a box put down on a slope at 0.9 of break-away moves
        // 66 µm, then 20 µm, at 120 Hz), and an elasto-plastic law with g_ba of a few µm would
        // take it for break-away and slide off at μ_k. The contact holds at its capacity, its
        // state seeded with the friction it carried; only a slip under a limit the law set
        // counts.
        // A slipping contact's friction is the law's sliding level whatever the warm start.
        if rec.regime == REGIME_NONE {
            // A contact the kernel meets loaded (rapier formed it in a step without the
            // adapter, or it was attached in contact): that solve was its cold one.
            rec.forming = FORMING_STEPS;
        }
        let was_holding = rec.slip_speed == 0.0;
        let giving_before = rec.forming == GIVING;
        let forming = rec.forming > 0 && !giving_before;
        let first_load = !(rec.mean_normal_force > 0.0);
        // Mean normal force for the tangential stiffness: filtered, seeded at first load.
        let f_mean = if !first_load {
            let tau = source.map_or(stiffness_time, |s| stiffness_time.max(5.0 / s.frequency()));
            let w = (dt / tau).min(1.0);
            rec.mean_normal_force as f64 + w * (f_n - rec.mean_normal_force as f64)
        } else {
            f_n
        };
        // Not under a vibration source: its load changes by design, and the law resolves
        // what that does to the contact.
        // The solve reached the limit the law gave it (the impulses are f32).
        let reached = rec.limit > 0.0 && mu_meas >= (1.0 - SATURATION) * rec.limit as f64;
        let give = !forming && can_stick && source.is_none() && gives(rec, input, reached, speed);
        let landing = forming || give;
        rec.forming = if give {
            GIVING
        } else if was_holding && input.warm_start < WARM {
            FORMING_STEPS
        } else if forming
            && rec.forming == 1
            && reached
            && speed > 0.0
            && speed <= one_step_slip(rec, input)
            && can_stick
            && source.is_none()
        {
            // The last forming step still brakes, at the limit, the slip the cold solve let
            // through (a load close to the capacity brakes it slowly: a box put down on a
            // slope at 0.95 of break-away takes three steps): the contact gives on while
            // that slip shrinks (see `gives`). A faster slip (put down on a moving belt) is
            // the law's.
            GIVING
        } else if giving_before {
            0
        } else {
            rec.forming.saturating_sub(1)
        };
        rec.mean_normal_force = f_mean as f32;
        let vib = source.map_or(1.0, |s| normal_factor(s, f_n, t_mid));
        // Time-resolved in-plane vibration on a compliant law while slipping: the law
        // integrates the seed's spring force S = s + a (see `vibration`).
        let compliant = match (source, law.stiffness()) {
            (Some(s), Some(c)) if s.mode() == VibrationMode::TimeResolved && s.has_in_plane() => {
                Some((s, c * f_mean))
            }
            _ => None,
        };
        let f_eff = f_n * vib;
        let measured = vec2::scale(measured_mu, f_n);
        let step_input = |slip: Vec2| StepInput {
            slip,
            dt,
            normal_force: f_eff,
            stiffness_normal_force: f_mean,
        };
        let saturated = !landing && reached;
        // A compliant contact under in-plane vibration cannot hold once the spring force it
        // carries, s + a(t), leaves the friction circle (Eq. 9): it slips now.
        let overloaded = compliant.is_some_and(|(s, _)| {
            let a = in_plane_force(s, f_mean, basis, rel, t_mid);
            vec2::norm(vec2::add(measured, a)) > law.static_coefficient() * f_eff
        });
        holding = !saturated && can_stick && !overloaded;
        let mut state = if holding {
            FrictionState::with_force(measured)
        } else {
            FrictionState {
                force: basis.project(rec.force),
                slide: rec.slide as f64,
            }
        };
        let out = if holding {
            law.step(&mut state, &step_input([0.0; 2]))
        } else {
            let g = slip_ahead(rec, slip, dt);
            match compliant {
                Some((s, k_t)) if k_t > 0.0 && k_t.is_finite() => {
                    let a0 = in_plane_force(s, f_mean, basis, rel, time);
                    let a1 = in_plane_force(s, f_mean, basis, rel, time + dt);
                    state.force = vec2::add(state.force, a0);
                    let g = vec2::add(g, vec2::scale(vec2::sub(a1, a0), 1.0 / k_t));
                    let out = law.step(&mut state, &step_input(g));
                    state.force = vec2::sub(state.force, a1);
                    out
                }
                _ => law.step(&mut state, &step_input(g)),
            }
        };
        // A memoryless law keeps no spring: a hold remembers the friction the constraint
        // carried instead (a jump in load is told by it, see `gives`).
        rec.force = basis.lift(if holding && law.is_memoryless() {
            measured
        } else {
            state.force
        });
        rec.slide = state.slide as f32;
        rec.regime = (if holding && (give || out.regime == Regime::Sliding) {
            Regime::StickSlip
        } else {
            out.regime
        })
        .code();
        // Holding: the law's capacity before it yields. Slipping: the law is resolved by the
        // step, so the solver applies exactly the law's force |μ⃗| F_n — except where the law
        // still calls the contact sticking without memory of a spring (a memoryless law below
        // its stick speed: the friction touched the limit but nothing slid), which keeps the
        // capacity; EP's elastic branch gives its spring force, c·F_n·g.
        let mu_law = if holding || (out.regime == Regime::Sticking && law.is_memoryless()) {
            out.limit
        } else {
            vec2::norm(out.mu)
        };
        limit = mu_law * vib;
        if compliant.is_some() && !holding {
            // The bodies feel the elastic part s of the spring force, exactly: saturate the
            // solver along −ŝ with a target relative velocity far beyond what one step's
            // friction impulse |s| dt can reach.
            limit = vec2::norm(state.force) / f_n;
            if let Some(dir) = vec2::normalize(state.force) {
                let along = vec2::normalize(slip).map_or(0.0, |e| vec2::dot(e, dir));
                if along < ALIGNED {
                    let reach = DIRECT_MARGIN * limit * f_n * dt * inv_mass + speed;
                    let v = vec2::sub(slip, vec2::scale(dir, reach));
                    if v.iter().all(|x| x.is_finite()) {
                        target = v;
                    }
                }
            }
        } else if let Some(s) = source {
            let (l, drive) = in_plane_limit(
                s, limit, f_n, f_mean, rel, basis, out.mu, slip, t_mid, holding, law,
            );
            limit = l;
            if let Some(v) = drive.filter(|v| v.iter().all(|x| x.is_finite())) {
                target = v;
            }
        }
        // A law without sticking (Regul), realized implicitly: the solver gets the full
        // sliding level and a target slip velocity equal to the law's creep speed under the
        // load it carried, ġ = ġ_t0 r⁻¹(|μ_meas|/μ_ve) along the load; at equilibrium that is
        // exactly the law.
        if let Some(creep) = law.creep(mu_meas, speed) {
            limit = creep.level;
            if let Some(dir) = vec2::normalize(measured_mu) {
                target = vec2::add(target, vec2::scale(dir, creep.speed));
            }
        }
    }
    let limit = limit.max(0.0);
    rec.limit = limit as f32;
    // A giving contact keeps its slip speed: the next step compares against it.
    rec.slip_speed = if holding && rec.forming != GIVING {
        0.0
    } else {
        speed as f32
    };
    ContactOutput {
        limit,
        target,
        holding,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_held_contact_steps_the_same_whatever_it_slips() {
        let law = ep();
        let b = basis();
        for (limit, mu) in [(0.5f32, [0.2, 0.1]), (0.55, [0.0, 0.4]), (0.5, [0.5, 0.0])] {
            let start = ContactState {
                limit,
                mean_normal_force: 100.0,
                force: [20.0, 0.0, 10.0],
                regime: Regime::Sticking.code(),
                ..ContactState::default()
            };
            let matters = slip_matters(&start, &law, None, 100.0, mu);
            let outputs: Vec<_> = [[0.0, 0.0], [1e-3, -2e-3], [0.3, 0.0]]
                .into_iter()
                .map(|slip| {
                    let mut rec = start;
                    let out = step_contact(&mut rec, &input(&law, &b, mu, slip));
                    (out, rec)
                })
                .collect();
            if !matters {
                assert!(outputs.iter().all(|o| *o == outputs[0]), "{outputs:?}");
            } else {
                // At the limit the slip decides between holding and slipping.
                assert!(outputs.iter().any(|o| *o != outputs[0]), "{outputs:?}");
            }
        }
    }
    use crate::sliding_curve::Curve;

    fn ep() -> Law {
        Law::elasto_plastic(1e5, 0.5, 0.5, Curve::constant(0.5).unwrap()).unwrap()
    }

    fn basis() -> TangentBasis {
        TangentBasis::plane([0.0, 1.0, 0.0], [1.0, 0.0, 0.0])
    }

    fn input<'a>(law: &'a Law, basis: &'a TangentBasis, mu: Vec2, slip: Vec2) -> ContactInput<'a> {
        ContactInput {
            law,
            source: None,
            rel: 1.0,
            basis,
            normal_force: 100.0,
            measured_mu: mu,
            slip,
            dt: 1.0 / 60.0,
            time: 0.0,
            inv_mass: 0.1,
            stiffness_time: 1.0,
            warm_start: 1.0,
        }
    }

    /// A contact that has held for a step (its limit set), carrying `mu`.
    fn held(law: &Law, mu: Vec2) -> ContactState {
        let b = basis();
        let mut rec = ContactState::default();
        step_contact(&mut rec, &input(law, &b, [0.0; 2], [0.0; 2]));
        step_contact(&mut rec, &input(law, &b, mu, [0.0; 2]));
        rec
    }

    #[test]
    fn rolling_without_slip_changes_nothing_and_corrects_nothing() {
        // A rolling contact: zero slip at the touching points, a steady friction share.
        let b = basis();
        for law in [ep(), Law::Coulomb(crate::law::Coulomb::new(0.5).unwrap())] {
            let mut rec = held(&law, [0.12, 0.0]);
            let before = rec;
            for _ in 0..100 {
                let out = step_contact(&mut rec, &input(&law, &b, [0.12, 0.0], [0.0; 2]));
                assert!(out.holding);
                assert_eq!(out.target, [0.0; 2]);
                assert_eq!(out.limit, 0.5);
            }
            assert_eq!(rec, before, "{}", law.name());
        }
    }

    #[test]
    fn a_held_contact_under_constant_load_neither_drifts_nor_corrects() {
        let b = basis();
        let law = ep();
        let mut rec = held(&law, [0.3, 0.1]);
        for _ in 0..1000 {
            let out = step_contact(&mut rec, &input(&law, &b, [0.3, 0.1], [0.0; 2]));
            assert!(out.holding);
            assert_eq!(out.target, [0.0; 2]);
        }
        let carried = b.project(rec.force);
        assert!((carried[0] - 30.0).abs() < 1e-3 && (carried[1] - 10.0).abs() < 1e-3);
        assert_eq!(rec.regime, Regime::Sticking.code());
    }

    #[test]
    fn a_hold_is_passive_over_a_closed_cycle() {
        // Load a held contact around a closed cycle of friction shares below break-away: the
        // solver only ever gets a zero target (no work done by the hold) and the state
        // returns to where it started.
        let b = basis();
        let law = ep();
        let mut rec = held(&law, [0.0, 0.0]);
        let start = rec;
        let n = 360;
        for k in 0..=n {
            let phase = std::f64::consts::TAU * k as f64 / n as f64;
            let mu = [0.4 * phase.sin(), 0.4 * (1.0 - phase.cos()) / 2.0];
            let out = step_contact(&mut rec, &input(&law, &b, mu, [0.0; 2]));
            assert!(out.holding && out.target == [0.0; 2]);
        }
        assert!(b.project(rec.force).iter().all(|x| x.abs() < 1e-9));
        assert_eq!(rec.slide, start.slide);
    }

    #[test]
    fn saturation_slips_and_the_law_integrates_the_slip_of_the_touching_points() {
        let b = basis();
        let law = ep();
        let mut rec = held(&law, [0.2, 0.0]);
        // The solver's friction reached the limit (0.5) and the contact slips at 1 m/s.
        let out = step_contact(&mut rec, &input(&law, &b, [0.5, 0.0], [1.0, 0.0]));
        assert!(!out.holding);
        assert_eq!(rec.regime, Regime::Sliding.code());
        assert!((out.limit - 0.5).abs() < 1e-6, "{}", out.limit);
        assert_eq!(out.target, [0.0; 2]);
    }

    #[test]
    fn a_memoryless_law_below_its_stick_speed_keeps_its_capacity() {
        // Phys: the friction touched the limit but nothing slid (a coupled contact in a
        // stack): the limit stays μ_ba, never the zero friction of "sliding at ġ = 0".
        let b = basis();
        let law =
            Law::Physical(crate::law::Physical::new(0.5, Curve::constant(0.4).unwrap()).unwrap());
        let mut rec = held(&law, [0.1, 0.0]);
        rec.limit = 0.1;
        let out = step_contact(&mut rec, &input(&law, &b, [0.1, 0.0], [1e-9, 0.0]));
        assert!(!out.holding);
        assert_eq!(out.limit, 0.5);
    }

    #[test]
    fn a_jump_in_load_gives_while_its_slip_slows_and_yields_when_it_grows() {
        // Held at 0.1 of a 0.5 limit, then the solve saturates with a slip one step of the
        // limit's impulse could make: the contact gives at its capacity (stick-slip) while
        // the slip shrinks; a slip that grows is the law's (EP, μ_k 0.3 < μ_s 0.5: it slides).
        let b = basis();
        let law = Law::elasto_plastic(1e5, 0.5, 0.5, Curve::constant(0.3).unwrap()).unwrap();
        for (slips, holds) in [([2e-3, 1e-3, 5e-4], true), ([2e-3, 3e-3, 4e-3], false)] {
            let mut rec = held(&law, [0.05, 0.0]);
            let mut out = None;
            for v in slips {
                out = Some(step_contact(
                    &mut rec,
                    &input(&law, &b, [0.5, 0.0], [v, 0.0]),
                ));
            }
            let out = out.unwrap();
            assert_eq!(out.holding, holds, "{slips:?}");
            if holds {
                assert_eq!(out.limit, 0.5);
                assert_eq!(rec.regime, Regime::StickSlip.code());
            } else {
                assert!(out.limit < 0.5, "the law yields: {}", out.limit);
            }
        }
        // An impact's slip (faster than one step of the limit's impulse) is the law's at once.
        let mut rec = held(&law, [0.05, 0.0]);
        let out = step_contact(&mut rec, &input(&law, &b, [0.5, 0.0], [1.0, 0.0]));
        assert!(!out.holding);
    }

    #[test]
    fn a_forming_contact_brakes_its_landing_slip_and_yields_only_to_a_growing_one() {
        // A box put down on a slope at 0.95 of break-away (μ_k 0.4 < μ_s 0.5): the cold solve
        // lets a slip through that the solver brakes at the limit over three steps, as the
        // load leaves little margin. The contact holds at its capacity while that slip
        // shrinks; a slip that keeps growing after forming, or one too fast for a step of the
        // limit to brake, is the law's (it slides).
        let b = basis();
        let law = Law::elasto_plastic(1e4, 0.5, 0.55, Curve::constant(0.4).unwrap()).unwrap();
        let step = |rec: &mut ContactState, mu: f64, v: f64| {
            let mut i = input(&law, &b, [mu, 0.0], [v, 0.0]);
            i.normal_force = 2215.0;
            i.inv_mass = 1.0 / 250.0;
            step_contact(rec, &i)
        };
        for (slips, holds) in [
            ([0.0108, 0.0071, 0.0034, 0.0], true),
            ([0.0108, 0.0120, 0.0140, 0.0160], false),
            // Put down on a belt: a slip one step of the limit cannot brake is the law's.
            ([0.34, 0.30, 0.26, 0.22], false),
        ] {
            let mut rec = ContactState::default();
            let mut first = input(&law, &b, [0.0; 2], [0.0; 2]);
            first.normal_force = 0.0;
            step_contact(&mut rec, &first);
            let mut out = None;
            for v in slips {
                out = Some(step(&mut rec, if v > 0.0 { 0.5 } else { 0.475 }, v));
            }
            let out = out.unwrap();
            assert_eq!(out.holding, holds, "{slips:?}");
            if holds {
                assert_eq!(out.limit, 0.5, "{slips:?}");
                assert_ne!(rec.regime, Regime::Sliding.code());
            } else {
                assert!(out.limit < 0.5, "the law yields: {}", out.limit);
            }
        }
    }

    #[test]
    fn garbage_inputs_reset_the_contact() {
        let b = basis();
        let law = ep();
        let mut rec = held(&law, [0.2, 0.0]);
        let mut bad = input(&law, &b, [f64::NAN, 0.0], [0.0; 2]);
        let out = step_contact(&mut rec, &bad);
        assert_eq!(rec.regime, REGIME_RESET);
        assert_eq!(out.limit, 0.5);
        bad.measured_mu = [0.0; 2];
        bad.slip = [f64::INFINITY, 0.0];
        step_contact(&mut rec, &bad);
        assert_eq!(rec.regime, REGIME_RESET);
        assert!(rec.force.iter().all(|x| x.is_finite()));
    }
}
