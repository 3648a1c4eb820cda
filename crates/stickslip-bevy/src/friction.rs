//! The friction layer on entities: which colliders are under stickslip, with which material,
//! vibrating how, moving how; applied to rapier before each step and taken out on removal.

use crate::components::RapierCollider;
use crate::convert::to_rapier;
use crate::world::StickSlipWorld;
use bevy::prelude::*;
use rapier3d::prelude as rp;
use stickslip_core::law::Law;
use stickslip_core::sliding_curve::Curve;
use stickslip_rapier::{FrictionMaterial, VibrationSource};

/// Puts a collider's contacts under stickslip's friction: its own material, or with
/// `FrictionLaw(None)` / `FrictionLaw::default()` the [`DefaultFriction`] resource's.
/// Removing it takes the collider back to plain rapier friction (and drops its vibration and
/// surface velocity, which only act through stickslip; they come back with the law).
#[derive(Component, Debug, Clone, Default, PartialEq)]
pub struct FrictionLaw(pub Option<FrictionMaterial>);

impl FrictionLaw {
    /// A collider with its own material.
    pub fn new(material: impl Into<FrictionMaterial>) -> Self {
        FrictionLaw(Some(material.into()))
    }
}

/// The material `FrictionLaw(None)` colliders use, like `StickSlip::new`'s default material:
/// [`default_material`] unless the app inserts its own. Changing it reaches those colliders at
/// the next step.
#[derive(Resource, Debug, Clone)]
pub struct DefaultFriction(pub FrictionMaterial);

impl Default for DefaultFriction {
    fn default() -> Self {
        DefaultFriction(default_material())
    }
}

/// Elasto-plastic, c = 1e5 1/m (break-away after g_ba = 5 µm), μ_ba = 0.5, sliding at 0.5.
pub fn default_material() -> FrictionMaterial {
    let curve = Curve::constant(0.5).expect("a positive coefficient");
    FrictionMaterial::new(Law::elasto_plastic(1e5, 0.5, 0.5, curve).expect("valid parameters"))
}

/// A vibration source on a collider (normal, tangential or transverse; time-resolved or
/// Popov-averaged): every contact of the collider feels it. Insert, change or remove at
/// will. Requires [`FrictionLaw`] (the default material unless the entity has its own).
#[derive(Component, Debug, Clone)]
#[require(FrictionLaw)]
pub struct Vibration(pub VibrationSource);

/// A moving surface (conveyor belt): the velocity (m/s, world frame) its contacts carry other
/// bodies along with, as rapier's target tangent velocity (the part normal to each contact is
/// dropped). Requires [`FrictionLaw`]: the surface acts through stickslip's contact hook.
#[derive(Component, Debug, Clone, Copy, PartialEq, Default)]
#[require(FrictionLaw)]
pub struct SurfaceVelocity(pub Vec3);

/// Puts a collider under stickslip with its law, vibration and surface velocity.
fn attach(
    w: &mut StickSlipWorld,
    h: rp::ColliderHandle,
    law: &FrictionLaw,
    vibration: Option<&Vibration>,
    surface: Option<&SurfaceVelocity>,
    defaults: &DefaultFriction,
) {
    let material = law.0.clone().unwrap_or_else(|| defaults.0.clone());
    w.friction
        .attach(&mut w.physics.colliders, h, Some(material));
    if let Some(v) = vibration {
        w.friction.set_vibration(h, v.0.clone());
    }
    if let Some(s) = surface {
        w.friction.inner_mut().surfaces.insert(h, to_rapier(s.0));
    }
}

/// Applies the friction layer's components to rapier colliders: new or re-created colliders
/// (their handle changed), and changed laws, vibrations, surfaces and default material.
#[allow(clippy::type_complexity)]
pub(crate) fn sync_friction(
    mut w: ResMut<StickSlipWorld>,
    defaults: Res<DefaultFriction>,
    laws: Query<
        (
            &RapierCollider,
            &FrictionLaw,
            Option<&Vibration>,
            Option<&SurfaceVelocity>,
        ),
        Or<(Changed<FrictionLaw>, Changed<RapierCollider>)>,
    >,
    vibrations: Query<(&RapierCollider, &Vibration), Changed<Vibration>>,
    surfaces: Query<(&RapierCollider, &SurfaceVelocity), Changed<SurfaceVelocity>>,
    all_laws: Query<(&RapierCollider, &FrictionLaw)>,
) {
    let w = &mut *w;
    // A new default reaches every collider that uses it.
    if defaults.is_changed() {
        for (h, _) in all_laws.iter().filter(|(_, law)| law.0.is_none()) {
            w.friction.set_material(h.0, defaults.0.clone());
        }
    }
    // A law (re)inserted also brings back the vibration and surface its removal dropped.
    for (h, law, vibration, surface) in &laws {
        attach(w, h.0, law, vibration, surface, &defaults);
    }
    for (h, v) in &vibrations {
        w.friction.set_vibration(h.0, v.0.clone());
    }
    for (h, s) in &surfaces {
        w.friction.inner_mut().surfaces.insert(h.0, to_rapier(s.0));
    }
}

/// Removing `FrictionLaw` takes the collider back to plain rapier friction.
pub(crate) fn on_remove_friction_law(
    remove: On<Remove, FrictionLaw>,
    mut w: ResMut<StickSlipWorld>,
) {
    if let Some(h) = w.collider(remove.entity) {
        w.detach(h);
    }
}

/// Removing `Vibration` stops the collider's vibration.
pub(crate) fn on_remove_vibration(remove: On<Remove, Vibration>, mut w: ResMut<StickSlipWorld>) {
    if let Some(h) = w.collider(remove.entity) {
        w.friction.remove_vibration(h);
    }
}

/// Removing `SurfaceVelocity` stops the surface.
pub(crate) fn on_remove_surface(
    remove: On<Remove, SurfaceVelocity>,
    mut w: ResMut<StickSlipWorld>,
) {
    if let Some(h) = w.collider(remove.entity) {
        w.friction.inner_mut().surfaces.remove(&h);
    }
}
