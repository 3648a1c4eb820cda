//! stickslip's replacement for bevy_rapier's step system: the very rapier steps bevy_rapier
//! would run in the frame (substeps, `Interpolated` catch-up included), each one bracketed by
//! `StickSlip::begin_step`/`end_step` — bevy_rapier's own system runs them all in one call,
//! where nothing can be done between two steps.

use crate::hooks::{StepHooks, UserHooks};
use crate::state::{LastRegimes, StickSlipRapier, publish_reports};
use bevy::ecs::system::{StaticSystemParam, SystemParam, SystemParamItem};
use bevy::prelude::*;
use bevy_rapier::plugin::context::{
    DefaultRapierContext, RapierContextColliders, RapierContextJoints, RapierContextSimulation,
    RapierRigidBodySet, SimulationToRenderTime,
};
use bevy_rapier::prelude::*;
use stickslip_bevy::{RegimeChanged, StickSlipContacts};

/// The rapier steps of one frame, exactly as bevy_rapier 0.36's `step_simulation` runs them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct FrameSteps {
    /// Rounds of `substeps` steps: 1, or `Interpolated`'s catch-up count (0 when the
    /// simulation is ahead of the render time).
    pub(crate) rounds: usize,
    /// Rapier steps per round.
    pub(crate) substeps: usize,
    /// The dt of every rapier step (s).
    pub(crate) step_dt: f32,
    /// The `integration_parameters.dt` bevy_rapier leaves behind (the frame's dt).
    pub(crate) frame_dt: f32,
    /// Whether the last round first records the bodies' poses for transform interpolation.
    pub(crate) interpolated: bool,
}

impl FrameSteps {
    /// The frame's steps in `mode` after `delta` seconds of render time; `Interpolated`
    /// moves `sim_to_render` (the simulation's lag behind the render time) as bevy_rapier
    /// does. A non-positive or non-finite `Interpolated` dt runs no step (bevy_rapier's loop
    /// would never end) and drops the lag.
    pub(crate) fn new(mode: TimestepMode, delta: f32, sim_to_render: &mut f32) -> FrameSteps {
        match mode {
            TimestepMode::Fixed { dt, substeps } => FrameSteps {
                rounds: 1,
                substeps,
                step_dt: dt / (substeps as f32),
                frame_dt: dt,
                interpolated: false,
            },
            TimestepMode::Variable {
                max_dt,
                time_scale,
                substeps,
            } => {
                let frame_dt = (delta * time_scale).min(max_dt);
                FrameSteps {
                    rounds: 1,
                    substeps,
                    step_dt: frame_dt / (substeps as f32),
                    frame_dt,
                    interpolated: false,
                }
            }
            TimestepMode::Interpolated {
                dt,
                time_scale,
                substeps,
            } => {
                let mut rounds = 0;
                *sim_to_render += delta;
                if dt > 0.0 && dt.is_finite() && sim_to_render.is_finite() {
                    // The same float operations as bevy_rapier's loop, so the same count.
                    while *sim_to_render > 0.0 {
                        rounds += 1;
                        *sim_to_render -= dt;
                    }
                } else {
                    // bevy_rapier would loop forever (dt <= 0) or step with NaN: no step.
                    static SAID: std::sync::atomic::AtomicBool =
                        std::sync::atomic::AtomicBool::new(false);
                    if !SAID.swap(true, std::sync::atomic::Ordering::Relaxed) {
                        error!(
                            "stickslip: TimestepMode::Interpolated with dt = {dt} s (or a \
                             non-finite lag) cannot be stepped; no rapier step runs"
                        );
                    }
                    *sim_to_render = 0.0;
                }
                FrameSteps {
                    rounds,
                    substeps,
                    step_dt: dt / (substeps as f32) * time_scale,
                    frame_dt: dt,
                    interpolated: true,
                }
            }
        }
    }
}

/// What a step writes besides the rapier context.
#[derive(SystemParam)]
pub(crate) struct StepOutputs<'w> {
    contacts: ResMut<'w, StickSlipContacts>,
    last: ResMut<'w, LastRegimes>,
    changed: MessageWriter<'w, RegimeChanged>,
    collision_events: MessageWriter<'w, CollisionEvent>,
    contact_force_events: MessageWriter<'w, ContactForceEvent>,
}

type Context = (
    &'static mut RapierContextSimulation,
    &'static mut RapierContextColliders,
    &'static mut RapierContextJoints,
    &'static mut RapierRigidBodySet,
    &'static RapierConfiguration,
    &'static mut SimulationToRenderTime,
    Has<DefaultRapierContext>,
);

/// bevy_rapier's `step_simulation::<H>`, one rapier step at a time: stickslip brackets the
/// steps of the default context; the app's hooks `H` run in every context.
pub(crate) fn step_simulation_bracketed<H>(
    mut contexts: Query<Context>,
    mode: Res<TimestepMode>,
    time: Res<Time>,
    mut state: ResMut<StickSlipRapier>,
    user: StaticSystemParam<H>,
    mut out: StepOutputs,
    mut interpolation: Query<(&RapierRigidBodyHandle, &mut TransformInterpolation)>,
) where
    H: SystemParam + 'static,
    for<'w, 's> SystemParamItem<'w, 's, H>: BevyPhysicsHooks,
{
    let user = &*user;
    let state = &mut *state;
    let out = &mut out;
    for (mut sim, mut colliders, mut joints, mut bodies, config, mut to_render, is_default) in
        &mut contexts
    {
        let (sim, colliders, joints, bodies) =
            (&mut *sim, &mut *colliders, &mut *joints, &mut *bodies);
        if !config.physics_pipeline_active {
            bodies.propagate_modified_body_positions_to_colliders(colliders);
            sim.send_bevy_events(&mut out.collision_events, &mut out.contact_force_events);
            continue;
        }
        let bracket = is_default && state.active;
        let steps = FrameSteps::new(*mode, time.delta_secs(), &mut to_render.diff);
        for round in 0..steps.rounds {
            if steps.interpolated && round + 1 == steps.rounds {
                // The poses the rendered transforms interpolate from, before the last round.
                for (handle, mut interpolation) in interpolation.iter_mut() {
                    if let Some(body) = bodies.bodies.get(handle.0) {
                        interpolation.start = Some(*body.position());
                        interpolation.end = None;
                    }
                }
            }
            for _ in 0..steps.substeps {
                if bracket {
                    state.modifier.wake_driven(
                        &sim.narrow_phase,
                        &colliders.colliders,
                        &mut bodies.bodies,
                    );
                    let mut params = sim.integration_parameters;
                    params.dt = steps.step_dt;
                    state
                        .modifier
                        .begin_step(&params, &bodies.bodies, &mut colliders.colliders);
                    // Rolling and spinning resistance: stickslip's own joints (and, for
                    // colliders without a body, its one fixed body) in the context's sets,
                    // without entities (bevy_rapier syncs only the entities it knows).
                    state.modifier.resist_rotation(
                        &params,
                        &mut joints.impulse_joints,
                        &sim.narrow_phase,
                        &mut bodies.bodies,
                        &colliders.colliders,
                    );
                }
                let hooks = StepHooks {
                    stickslip: bracket.then_some(&state.modifier),
                    user: UserHooks { user },
                };
                // One rapier step: bevy_rapier's Fixed mode with one substep of this dt.
                sim.step_simulation(
                    colliders,
                    joints,
                    bodies,
                    config.gravity,
                    TimestepMode::Fixed {
                        dt: steps.step_dt,
                        substeps: 1,
                    },
                    Some((&out.collision_events, &out.contact_force_events)),
                    &hooks,
                    &time,
                    &mut to_render,
                    None,
                );
                // Each call replaces the context's pending events: send them now.
                sim.send_bevy_events(&mut out.collision_events, &mut out.contact_force_events);
                if bracket {
                    state.modifier.end_step(
                        &sim.narrow_phase,
                        &bodies.bodies,
                        &mut colliders.colliders,
                    );
                    publish_reports(
                        state,
                        &colliders.colliders,
                        &mut out.contacts,
                        &mut out.last,
                        &mut out.changed,
                    );
                }
            }
        }
        sim.integration_parameters.dt = steps.frame_dt;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// bevy_rapier's Interpolated loop, verbatim, counting rounds.
    fn bevy_rapier_rounds(dt: f32, delta: f32, diff: &mut f32) -> usize {
        let mut n = 0;
        *diff += delta;
        while *diff > 0.0 {
            n += 1;
            *diff -= dt;
        }
        n
    }

    #[test]
    fn interpolated_rounds_match_bevy_rapiers_loop() {
        let (mut a, mut b) = (0.0f32, 0.0f32);
        let mode = TimestepMode::Interpolated {
            dt: 1.0 / 60.0,
            time_scale: 1.0,
            substeps: 2,
        };
        // Frames of uneven length: catch-up rounds of 0, 1, 2, ….
        for k in 0..500 {
            let delta = [0.0, 1.0 / 144.0, 1.0 / 30.0, 0.05, 1.0 / 60.0][k % 5];
            let steps = FrameSteps::new(mode, delta, &mut a);
            assert_eq!(steps.rounds, bevy_rapier_rounds(1.0 / 60.0, delta, &mut b));
            assert_eq!(a.to_bits(), b.to_bits());
            assert_eq!(steps.step_dt, 1.0 / 60.0 / 2.0);
        }
    }

    #[test]
    fn a_degenerate_interpolated_dt_runs_nothing_and_never_hangs() {
        for dt in [0.0, -1.0, f32::NAN, f32::INFINITY] {
            let mut lag = 0.0;
            let mode = TimestepMode::Interpolated {
                dt,
                time_scale: 1.0,
                substeps: 1,
            };
            assert_eq!(FrameSteps::new(mode, 0.1, &mut lag).rounds, 0);
            assert_eq!(lag, 0.0);
        }
    }
}
