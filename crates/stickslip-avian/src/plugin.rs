//! The plugin: its resources and where its systems run in avian's `PhysicsSchedule`.

use crate::apply::apply;
use crate::measure::{accumulate, carry_warm_start, measure};
use crate::pair_law::PairLaws;
use crate::rolling::{Rolling, collect, relax_rows, solve_rows, warm_start};
use crate::store::ContactStore;
use avian::collision::narrow_phase::NarrowPhaseSystems;
use avian::dynamics::integrator::IntegrationSystems;
use avian::dynamics::solver::islands::WakeBody;
use avian::dynamics::solver::schedule::{SolverSystems, SubstepSchedule, SubstepSolverSystems};
use avian::dynamics::solver::xpbd::XpbdSolverSystems;
use avian::prelude::*;
use bevy::prelude::*;
use stickslip_bevy::{
    RegimeChanged, StickSlipContacts, StickSlipFriction, StickSlipRolling, StickSlipVibration,
    SurfaceVelocity,
};
use stickslip_core::FrictionMaterial;
use stickslip_core::law::{Coulomb, Law};
use stickslip_core::sliding_curve::Curve;

/// stickslip for an avian3d app: add it beside `PhysicsPlugins` (in any order; it needs
/// avian's plugins to be there when the app runs).
pub struct StickSlipAvianPlugin {
    default_material: FrictionMaterial,
}

impl StickSlipAvianPlugin {
    /// stickslip with this material for colliders marked `StickSlipFriction(None)`.
    pub fn new(default_material: FrictionMaterial) -> Self {
        StickSlipAvianPlugin { default_material }
    }
}

impl Default for StickSlipAvianPlugin {
    /// Elasto-plastic friction with avian's default coefficient 0.5 for break-away, static
    /// and sliding friction, contact stiffness c = 1e5 1/m: sticking without creep.
    fn default() -> Self {
        let law = Curve::constant(0.5)
            .and_then(|c| Law::elasto_plastic(1e5, 0.5, 0.5, c))
            .unwrap_or_else(|_| Law::Coulomb(Coulomb::clamped(0.5)));
        StickSlipAvianPlugin::new(FrictionMaterial::new(law))
    }
}

/// The plugin's settings.
#[derive(Resource, Debug, Clone)]
pub(crate) struct StickSlipAvianConfig {
    /// The material of `StickSlipFriction(None)`.
    pub default_material: FrictionMaterial,
    /// Averaging time of a contact's mean normal force (s), as rapier's adapter.
    pub stiffness_time: f64,
}

/// stickslip's systems in avian's `PhysicsSchedule`, for apps that order their own around
/// them.
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum StickSlipAvianSystems {
    /// The law's step on every contact, at the end of the narrow phase.
    Apply,
    /// The solve's measurement and the read-back, right after the solver stored its
    /// impulses.
    Measure,
}

impl Plugin for StickSlipAvianPlugin {
    fn build(&self, app: &mut App) {
        app.insert_resource(StickSlipAvianConfig {
            default_material: self.default_material.clone(),
            stiffness_time: 1.0,
        })
        .init_resource::<ContactStore>()
        .init_resource::<PairLaws>()
        .init_resource::<StickSlipContacts>()
        .init_resource::<Rolling>()
        .init_resource::<StickSlipRolling>()
        .add_message::<RegimeChanged>()
        .configure_sets(
            PhysicsSchedule,
            (
                StickSlipAvianSystems::Apply.in_set(NarrowPhaseSystems::Last),
                StickSlipAvianSystems::Measure
                    .in_set(PhysicsStepSystems::Solver)
                    .after(SolverSystems::StoreContactImpulses),
            ),
        )
        .add_systems(
            PhysicsSchedule,
            (
                (forget_changed_materials, apply)
                    .chain()
                    .in_set(StickSlipAvianSystems::Apply),
                carry_warm_start.in_set(SolverSystems::PreSubstep),
                (measure, collect).in_set(StickSlipAvianSystems::Measure),
                wake_driven.in_set(PhysicsStepSystems::First),
            ),
        )
        .add_systems(
            SubstepSchedule,
            (
                accumulate.after(SubstepSolverSystems::Relax),
                // Rolling resistance's rows, each pass after avian's contact rows.
                warm_start
                    .after(SubstepSolverSystems::WarmStart)
                    .before(SubstepSolverSystems::SolveConstraints),
                solve_rows
                    .after(SubstepSolverSystems::SolveConstraints)
                    .before(IntegrationSystems::Position),
                relax_rows
                    .after(SubstepSolverSystems::Relax)
                    .before(XpbdSolverSystems::SolveConstraints)
                    .before(SubstepSolverSystems::Damping),
            ),
        );
    }
}

/// A surface that starts moving or vibrating wakes what sleeps on it (while it moves, `apply`
/// keeps what it touches awake).
#[allow(clippy::type_complexity)]
fn wake_driven(
    driven: Query<Entity, Or<(Changed<SurfaceVelocity>, Changed<StickSlipVibration>)>>,
    graph: Res<ContactGraph>,
    sleeping: Query<(), With<Sleeping>>,
    mut commands: Commands,
) {
    for e in &driven {
        for pair in graph.contact_pairs_with(e) {
            for body in [pair.body1, pair.body2].into_iter().flatten() {
                if sleeping.contains(body) {
                    commands.queue(WakeBody(body));
                }
            }
        }
    }
}

/// A material that changed or went: the combined laws start over.
fn forget_changed_materials(
    changed: Query<(), Changed<StickSlipFriction>>,
    mut removed: RemovedComponents<StickSlipFriction>,
    mut laws: ResMut<PairLaws>,
) {
    if !changed.is_empty() || removed.read().next().is_some() {
        laws.clear();
    }
}
