//! Validation and construction: [`Scenario`] → [`Scene`] (a rapier world, the stickslip
//! modifier and the drivers).

use crate::error::BuildError;
use crate::limits::*;
use crate::spec::{
    BodyKind, BodySpec, ColliderSpec, DEFAULT_STEPS, DriverSpec, FrictionModelSpec, Scenario,
    ShapeSpec,
};
use rapier3d::glamx::EulerRot;
use rapier3d::prelude::*;
use std::collections::{BTreeMap, HashMap, HashSet};
use stickslip_core::law::{Coulomb, Law};
use stickslip_core::profile::ForceProfile;
use stickslip_core::waveform::Waveform;
use stickslip_rapier::{
    FrictionMaterial, StickSlip, StickSlipConfig, VibrationComponent, VibrationSource,
};

/// A built scenario: everything a [`crate::Runner`] steps and a logger reads.
pub struct Scene {
    /// The scenario's name.
    pub name: String,
    /// The rapier world.
    pub world: PhysicsWorld,
    /// The contact modifier (materials attached, vibration sources set).
    pub stickslip: StickSlip,
    /// Bodies in file order (repeated bodies expanded).
    pub bodies: Vec<SceneBody>,
    /// Colliders in file order.
    pub colliders: Vec<SceneCollider>,
    /// Drivers applied before each step.
    pub drivers: Vec<Driver>,
    /// Steps the scenario asks for.
    pub steps: u64,
    /// Log every k-th step.
    pub log_every: u64,
    /// Per-contact series limit for loggers.
    pub max_contact_series: usize,
}

/// A body of the scene.
#[derive(Debug, Clone)]
pub struct SceneBody {
    /// Unique name (`NAME` or `NAME_i` for repeated bodies).
    pub name: String,
    /// The `[[body]]` name it came from.
    pub group: String,
    /// rapier handle.
    pub handle: RigidBodyHandle,
    /// Its type.
    pub kind: BodyKind,
    /// Position at t = 0 (m).
    pub start: [f64; 3],
}

/// A collider of the scene.
#[derive(Debug, Clone)]
pub struct SceneCollider {
    /// Index of its body in [`Scene::bodies`].
    pub body: usize,
    /// Index among its body's colliders.
    pub index: usize,
    /// rapier handle.
    pub handle: ColliderHandle,
    /// Its shape.
    pub shape: ShapeSpec,
    /// Whether its contacts use stickslip.
    pub stickslip: bool,
    /// Name of its vibration source.
    pub vibration: Option<String>,
}

/// A driver acting on one body.
#[derive(Debug, Clone)]
pub struct Driver {
    /// Index of the body in [`Scene::bodies`].
    pub body: usize,
    /// What it does.
    pub action: DriverAction,
}

/// What a [`Driver`] does each step (see [`DriverSpec`] for the meaning).
#[derive(Debug, Clone)]
pub enum DriverAction {
    /// Sets a kinematic body's velocity from `start` on.
    Velocity {
        /// Linear velocity (m/s).
        linear: Vector,
        /// Angular velocity (rad/s).
        angular: Vector,
        /// Start time (s).
        start: f64,
    },
    /// Spring from a body point to a moving anchor.
    Spring {
        /// Stiffness (N/m).
        stiffness: f64,
        /// Damping (N·s/m).
        damping: f64,
        /// Anchor at t = 0 (m, world).
        anchor: [f64; 3],
        /// Anchor velocity (m/s).
        anchor_velocity: [f64; 3],
        /// Attachment point in the body frame (m).
        point: Vector,
        /// Unit axis the spring is restricted to.
        axis: Option<[f64; 3]>,
    },
    /// F(t) along a unit direction.
    Force {
        /// Unit direction.
        direction: [f64; 3],
        /// F(t) (N).
        profile: ForceProfile,
        /// Point of application in the body frame, or the center of mass.
        point: Option<Vector>,
    },
}

fn invalid(field: impl Into<String>, reason: impl Into<String>) -> BuildError {
    BuildError::InvalidValue {
        field: field.into(),
        reason: reason.into(),
    }
}

fn finite(field: &str, v: f64) -> Result<f64, BuildError> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(invalid(field, format!("must be finite, got {v}")))
    }
}

fn finite3(field: &str, v: [f64; 3]) -> Result<[f64; 3], BuildError> {
    if v.iter().all(|x| x.is_finite()) {
        Ok(v)
    } else {
        Err(invalid(field, format!("must be finite, got {v:?}")))
    }
}

/// A number that becomes an f32 in rapier: finite and at most [`MAX_MAGNITUDE`] in size.
fn magnitude(field: &str, v: f64) -> Result<f64, BuildError> {
    finite(field, v)?;
    if v.abs() <= MAX_MAGNITUDE {
        Ok(v)
    } else {
        Err(invalid(
            field,
            format!("|{v}| exceeds {MAX_MAGNITUDE:e}, beyond what rapier's f32 world can hold"),
        ))
    }
}

fn magnitude3(field: &str, v: [f64; 3]) -> Result<[f64; 3], BuildError> {
    for (k, x) in v.iter().enumerate() {
        magnitude(&format!("{field}[{k}]"), *x)?;
    }
    Ok(v)
}

/// A positive number that becomes an f32 in rapier, in `[min, MAX_MAGNITUDE]`.
fn positive_at_least(field: &str, v: f64, min: f64) -> Result<f64, BuildError> {
    magnitude(field, v)?;
    if v >= min {
        Ok(v)
    } else {
        Err(invalid(field, format!("must be >= {min:e}, got {v}")))
    }
}

/// A count in `[1, max]`.
fn count(field: &str, v: u64, max: u64) -> Result<u64, BuildError> {
    if (1..=max).contains(&v) {
        Ok(v)
    } else {
        Err(invalid(field, format!("must be in 1..={max}, got {v}")))
    }
}

fn positive(field: &str, v: f64) -> Result<f64, BuildError> {
    finite(field, v)?;
    if v > 0.0 {
        Ok(v)
    } else {
        Err(invalid(field, format!("must be > 0, got {v}")))
    }
}

fn non_negative(field: &str, v: f64) -> Result<f64, BuildError> {
    finite(field, v)?;
    if v >= 0.0 {
        Ok(v)
    } else {
        Err(invalid(field, format!("must be >= 0, got {v}")))
    }
}

fn unit(field: &str, v: [f64; 3]) -> Result<[f64; 3], BuildError> {
    finite3(field, v)?;
    let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if n > 1e-12 {
        Ok([v[0] / n, v[1] / n, v[2] / n])
    } else {
        Err(invalid(field, "must be a non-zero vector"))
    }
}

fn vec3(v: [f64; 3]) -> Vector {
    Vector::new(v[0] as f32, v[1] as f32, v[2] as f32)
}

fn rotation(deg: [f64; 3]) -> Rotation {
    Rotation::from_euler(
        EulerRot::XYZ,
        deg[0].to_radians() as f32,
        deg[1].to_radians() as f32,
        deg[2].to_radians() as f32,
    )
}

fn check_name(field: &str, name: &str) -> Result<(), BuildError> {
    if name.is_empty()
        || !name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
    {
        return Err(invalid(
            field,
            format!("`{name}` must be non-empty and use only letters, digits, `_` and `-`"),
        ));
    }
    Ok(())
}

fn unknown<'a>(
    field: String,
    what: &'static str,
    name: &str,
    known: impl Iterator<Item = &'a String>,
) -> BuildError {
    BuildError::Unknown {
        field,
        what,
        name: name.to_string(),
        known: known.cloned().collect(),
    }
}

impl Scenario {
    /// Number of steps the run takes: `steps`, else `duration / dt` rounded up, else
    /// [`DEFAULT_STEPS`].
    pub fn steps(&self) -> u64 {
        match (self.run.steps, self.run.duration) {
            (Some(n), _) => n,
            (None, Some(d)) if self.world.dt > 0.0 && d.is_finite() => {
                (d / self.world.dt - 1e-9).ceil().max(1.0) as u64
            }
            _ => DEFAULT_STEPS,
        }
    }

    /// The default material's name (see [`crate::spec::StickSlipSpec::default_material`]).
    fn default_material(&self) -> Result<Option<&str>, BuildError> {
        if let Some(name) = &self.stickslip.default_material {
            if !self.materials.contains_key(name) {
                return Err(unknown(
                    "stickslip.default_material".into(),
                    "material",
                    name,
                    self.materials.keys(),
                ));
            }
            return Ok(Some(name));
        }
        Ok(match self.materials.len() {
            1 => self.materials.keys().next().map(String::as_str),
            _ => None,
        })
    }

    /// Checks every value and reference without building anything.
    pub fn validate(&self) -> Result<(), BuildError> {
        // The name is rerun's application id, which must not be empty.
        if self.name.trim().is_empty() {
            return Err(invalid(
                "name",
                "must not be empty (it names the run, and is rerun's application id)",
            ));
        }
        let w = &self.world;
        magnitude3("world.gravity", w.gravity)?;
        positive("world.dt", w.dt)?;
        if !(MIN_DT..=MAX_DT).contains(&w.dt) {
            return Err(invalid(
                "world.dt",
                format!("must be in [{MIN_DT:e}, {MAX_DT}] s, got {}", w.dt),
            ));
        }
        count(
            "world.solver_iterations",
            w.solver_iterations as u64,
            MAX_SOLVER_ITERATIONS as u64,
        )?;
        let r = &self.run;
        if r.steps.is_some() && r.duration.is_some() {
            return Err(invalid(
                "run",
                "give either `steps` or `duration`, not both",
            ));
        }
        if r.steps == Some(0) {
            return Err(invalid("run.steps", "must be >= 1"));
        }
        if let Some(n) = r.steps {
            count("run.steps", n, MAX_STEPS)?;
        }
        if let Some(d) = r.duration {
            positive("run.duration", d)?;
            // In f64: a duration/dt beyond u64 must not wrap around to a short run.
            if d / w.dt > MAX_STEPS as f64 {
                return Err(invalid(
                    "run.duration",
                    format!("{d} s at dt = {} s is more than {MAX_STEPS} steps", w.dt),
                ));
            }
        }
        if r.log_every == 0 {
            return Err(invalid("run.log_every", "must be >= 1"));
        }
        if r.max_contact_series > MAX_CONTACT_SERIES {
            return Err(invalid(
                "run.max_contact_series",
                format!(
                    "must be <= {MAX_CONTACT_SERIES}, got {}",
                    r.max_contact_series
                ),
            ));
        }
        // Sizes before anything is allocated per body: a repeat count of 1e9 is an error
        // here, not a billion names below.
        let (mut bodies, mut colliders) = (0u64, 0u64);
        for (i, b) in self.bodies.iter().enumerate() {
            let n = match &b.repeat {
                Some(rep) => count(
                    &format!("body[{i}].repeat.count"),
                    rep.count as u64,
                    MAX_BODIES,
                )?,
                None => 1,
            };
            bodies += n;
            colliders += n * b.colliders.len() as u64;
            if bodies > MAX_BODIES {
                return Err(invalid(
                    format!("body[{i}]"),
                    format!("the scenario has more than {MAX_BODIES} bodies (repeats expanded)"),
                ));
            }
            if colliders > MAX_COLLIDERS {
                return Err(invalid(
                    format!("body[{i}].collider"),
                    format!(
                        "the scenario has more than {MAX_COLLIDERS} colliders (repeats expanded)"
                    ),
                ));
            }
        }
        let work = self.steps().saturating_mul(bodies + colliders);
        if work > MAX_WORK {
            let field = if r.duration.is_some() {
                "run.duration"
            } else {
                "run.steps"
            };
            return Err(invalid(
                field,
                format!(
                    "{} steps x {} bodies and colliders = {work:e} exceeds {MAX_WORK:e} \
                     (about an hour per 1e10 on this kind of machine); shorten the run",
                    self.steps(),
                    bodies + colliders
                ),
            ));
        }
        self.config()?;
        let default_material = self.default_material()?;
        for name in self.vibrations.keys() {
            self.vibration_source(name)?;
        }
        let mut names: HashSet<String> = HashSet::new();
        let mut groups: HashMap<&str, BodyKind> = HashMap::new();
        for (i, b) in self.bodies.iter().enumerate() {
            let f = |k: &str| format!("body[{i}].{k}");
            check_name(&f("name"), &b.name)?;
            let mut add = |name: String| -> Result<(), BuildError> {
                if names.contains(&name) {
                    return Err(BuildError::DuplicateBody {
                        field: f("name"),
                        name,
                    });
                }
                names.insert(name);
                Ok(())
            };
            match &b.repeat {
                None => add(b.name.clone())?,
                Some(rep) => {
                    magnitude3(&f("repeat.offset"), rep.offset)?;
                    // The group name itself is taken too (drivers address the group by it).
                    add(b.name.clone())?;
                    for k in 0..rep.count {
                        add(format!("{}_{k}", b.name))?;
                    }
                }
            }
            groups.insert(&b.name, b.kind);
            magnitude3(&f("position"), b.position)?;
            if let Some(rep) = &b.repeat {
                // The last copy must be as representable as the first.
                let last = std::array::from_fn(|k| {
                    b.position[k] + rep.offset[k] * (rep.count as f64 - 1.0)
                });
                magnitude3(&f("repeat.offset"), last)?;
            }
            magnitude3(&f("rotation_deg"), b.rotation_deg)?;
            magnitude3(&f("linvel"), b.linvel)?;
            magnitude3(&f("angvel"), b.angvel)?;
            non_negative(&f("linear_damping"), b.linear_damping)?;
            non_negative(&f("angular_damping"), b.angular_damping)?;
            magnitude(&f("linear_damping"), b.linear_damping)?;
            magnitude(&f("angular_damping"), b.angular_damping)?;
            if b.kind == BodyKind::Dynamic && b.colliders.is_empty() {
                return Err(invalid(
                    f("collider"),
                    "a dynamic body needs at least one collider (it has no mass otherwise)",
                ));
            }
            for (j, c) in b.colliders.iter().enumerate() {
                self.validate_collider(&format!("body[{i}].collider[{j}]"), c, default_material)?;
            }
        }
        for (i, d) in self.drivers.iter().enumerate() {
            self.validate_driver(i, d, &groups)?;
        }
        Ok(())
    }

    fn config(&self) -> Result<StickSlipConfig, BuildError> {
        let mut cfg = StickSlipConfig::default();
        if let Some(v) = self.stickslip.stiffness_time {
            cfg.stiffness_time = v;
        }
        cfg.validate().map_err(|source| BuildError::Param {
            field: "stickslip".into(),
            source,
        })?;
        Ok(cfg)
    }

    fn vibration_source(&self, name: &str) -> Result<VibrationSource, BuildError> {
        let v = &self.vibrations[name];
        let field = format!("vibration.{name}");
        let param = |source| BuildError::Param {
            field: field.clone(),
            source,
        };
        let inline = v.direction.is_some()
            || v.amplitude.is_some()
            || v.waveform.is_some()
            || v.phase.is_some();
        let components = if v.components.is_empty() {
            let missing = |what: &str| BuildError::InvalidValue {
                field: format!("{field}.{what}"),
                reason: "missing: give direction and amplitude, or components".into(),
            };
            vec![
                VibrationComponent::new(
                    v.direction.ok_or_else(|| missing("direction"))?,
                    v.amplitude.ok_or_else(|| missing("amplitude"))?,
                    v.waveform.clone().unwrap_or(Waveform::Sine),
                    v.phase.unwrap_or(0.0),
                )
                .map_err(param)?,
            ]
        } else if inline {
            return Err(BuildError::InvalidValue {
                field: format!("{field}.components"),
                reason: "give either direction/amplitude/waveform/phase or components, not both"
                    .into(),
            });
        } else {
            v.components
                .iter()
                .enumerate()
                .map(|(i, c)| {
                    VibrationComponent::new(c.direction, c.amplitude, c.waveform.clone(), c.phase)
                        .map_err(|source| BuildError::Param {
                            field: format!("{field}.components[{i}]"),
                            source,
                        })
                })
                .collect::<Result<Vec<_>, _>>()?
        };
        let mut s =
            VibrationSource::superimposed(&components, v.frequency, v.mode).map_err(param)?;
        if let Some(k) = v.tangential_stiffness {
            s = s.with_tangential_stiffness(k).map_err(param)?;
        }
        Ok(s)
    }

    fn validate_collider(
        &self,
        f: &str,
        c: &ColliderSpec,
        default_material: Option<&str>,
    ) -> Result<(), BuildError> {
        match &c.shape {
            ShapeSpec::Cuboid { half_extents } => {
                for (k, &h) in half_extents.iter().enumerate() {
                    positive_at_least(&format!("{f}.shape.half_extents[{k}]"), h, MIN_SIZE)?;
                }
            }
            ShapeSpec::Ball { radius } => {
                positive_at_least(&format!("{f}.shape.radius"), *radius, MIN_SIZE)?;
            }
            ShapeSpec::Capsule {
                half_height,
                radius,
            } => {
                positive_at_least(&format!("{f}.shape.half_height"), *half_height, MIN_SIZE)?;
                positive_at_least(&format!("{f}.shape.radius"), *radius, MIN_SIZE)?;
            }
        }
        magnitude3(&format!("{f}.offset"), c.offset)?;
        magnitude3(&format!("{f}.rotation_deg"), c.rotation_deg)?;
        if c.density.is_some() && c.mass.is_some() {
            return Err(invalid(f, "give either `density` or `mass`, not both"));
        }
        if let Some(d) = c.density {
            positive_at_least(&format!("{f}.density"), d, MIN_MASS)?;
        }
        if let Some(m) = c.mass {
            positive_at_least(&format!("{f}.mass"), m, MIN_MASS)?;
        }
        non_negative(&format!("{f}.friction"), c.friction)?;
        magnitude(&format!("{f}.friction"), c.friction)?;
        let r = non_negative(&format!("{f}.restitution"), c.restitution)?;
        if r > 1.0 {
            return Err(invalid(
                format!("{f}.restitution"),
                format!("must be <= 1, got {r}"),
            ));
        }
        if let Some(m) = &c.material
            && !self.materials.contains_key(m)
        {
            return Err(unknown(
                format!("{f}.material"),
                "material",
                m,
                self.materials.keys(),
            ));
        }
        if c.stickslip && c.material.is_none() && default_material.is_none() {
            return Err(invalid(
                format!("{f}.stickslip"),
                "no default material: set `material` here or `[stickslip] default_material`",
            ));
        }
        if let Some(v) = &c.vibration
            && !self.vibrations.contains_key(v)
        {
            return Err(unknown(
                format!("{f}.vibration"),
                "vibration",
                v,
                self.vibrations.keys(),
            ));
        }
        Ok(())
    }

    fn validate_driver(
        &self,
        i: usize,
        d: &DriverSpec,
        groups: &HashMap<&str, BodyKind>,
    ) -> Result<(), BuildError> {
        let f = |k: &str| format!("driver[{i}].{k}");
        let name = d.body();
        let kind = self.body_kind(name).ok_or_else(|| {
            let mut known: Vec<String> = groups.keys().map(|s| s.to_string()).collect();
            known.sort();
            BuildError::Unknown {
                field: f("body"),
                what: "body",
                name: name.to_string(),
                known,
            }
        })?;
        let kind_name = |k: BodyKind| match k {
            BodyKind::Fixed => "fixed",
            BodyKind::Dynamic => "dynamic",
            BodyKind::Kinematic => "kinematic",
        };
        let need = |driver: &'static str, needs: BodyKind| {
            if kind == needs {
                Ok(())
            } else {
                Err(BuildError::WrongBodyKind {
                    field: f("body"),
                    driver,
                    needs: kind_name(needs),
                    body: name.to_string(),
                    is: kind_name(kind),
                })
            }
        };
        match d {
            DriverSpec::Velocity {
                velocity,
                angular,
                start,
                ..
            } => {
                need("velocity", BodyKind::Kinematic)?;
                magnitude3(&f("velocity"), *velocity)?;
                magnitude3(&f("angular"), *angular)?;
                non_negative(&f("start"), *start)?;
            }
            DriverSpec::Spring {
                stiffness,
                damping,
                anchor_offset,
                anchor_velocity,
                point,
                axis,
                ..
            } => {
                need("spring", BodyKind::Dynamic)?;
                non_negative(&f("stiffness"), *stiffness)?;
                non_negative(&f("damping"), *damping)?;
                magnitude(&f("stiffness"), *stiffness)?;
                magnitude(&f("damping"), *damping)?;
                magnitude3(&f("anchor_offset"), *anchor_offset)?;
                magnitude3(&f("anchor_velocity"), *anchor_velocity)?;
                magnitude3(&f("point"), *point)?;
                if let Some(a) = axis {
                    unit(&f("axis"), *a)?;
                }
            }
            DriverSpec::Force {
                direction,
                knots,
                point,
                ..
            } => {
                need("force", BodyKind::Dynamic)?;
                unit(&f("direction"), *direction)?;
                for (k, knot) in knots.iter().enumerate() {
                    magnitude(&f(&format!("knots[{k}][1]")), knot[1])?;
                }
                profile(&f("knots"), knots)?;
                if let Some(p) = point {
                    magnitude3(&f("point"), *p)?;
                }
            }
        }
        Ok(())
    }

    fn body_kind(&self, name: &str) -> Option<BodyKind> {
        self.bodies.iter().find_map(|b| {
            let hit = b.name == name
                || b.repeat.as_ref().is_some_and(|r| {
                    name.strip_prefix(&b.name)
                        .and_then(|s| s.strip_prefix('_'))
                        .and_then(|k| k.parse::<u32>().ok())
                        .is_some_and(|k| k < r.count)
                });
            hit.then_some(b.kind)
        })
    }

    /// Validates and builds the world, the modifier and the drivers.
    pub fn build(&self) -> Result<Scene, BuildError> {
        self.validate()?;
        let mut world = PhysicsWorld::default();
        world.gravity = vec3(self.world.gravity);
        let params = &mut world.integration_parameters;
        params.dt = self.world.dt as f32;
        params.num_solver_iterations = self.world.solver_iterations;
        params.friction_model = match self.world.friction_model {
            FrictionModelSpec::Simplified => FrictionModel::Simplified,
            FrictionModelSpec::Coulomb => FrictionModel::Coulomb,
        };

        let default_material = match self.default_material()? {
            Some(name) => self.materials[name].clone(),
            None => match self.materials.values().next() {
                // Only reached when no collider relies on the default.
                Some(law) => law.clone(),
                None => Law::Coulomb(Coulomb::new(0.5).map_err(|source| BuildError::Param {
                    field: "material".into(),
                    source,
                })?),
            },
        };
        // The runner, its rerun logging and the bevy scenario view read every contact.
        let mut stickslip = StickSlip::new(FrictionMaterial::new(default_material))
            .with_read_back(stickslip_rapier::ReadBack::Contacts)
            .with_config(self.config()?)
            .map_err(|source| BuildError::Param {
                field: "stickslip".into(),
                source,
            })?;
        let mut sources: BTreeMap<&str, VibrationSource> = BTreeMap::new();
        for name in self.vibrations.keys() {
            sources.insert(name, self.vibration_source(name)?);
        }

        let mut bodies = Vec::new();
        let mut colliders = Vec::new();
        for b in &self.bodies {
            let count = b.repeat.as_ref().map_or(1, |r| r.count);
            for k in 0..count {
                let shift = b
                    .repeat
                    .as_ref()
                    .map_or([0.0; 3], |r| r.offset.map(|o| o * k as f64));
                let start = [
                    b.position[0] + shift[0],
                    b.position[1] + shift[1],
                    b.position[2] + shift[2],
                ];
                let name = match b.repeat {
                    Some(_) => format!("{}_{k}", b.name),
                    None => b.name.clone(),
                };
                let handle = world.insert_body(body_builder(b, start));
                let body_index = bodies.len();
                for (j, c) in b.colliders.iter().enumerate() {
                    let ch = world.insert_collider(collider_builder(c), Some(handle));
                    let attached = c.stickslip || c.material.is_some() || c.vibration.is_some();
                    if attached {
                        let material = c
                            .material
                            .as_ref()
                            .map(|m| FrictionMaterial::new(self.materials[m].clone()));
                        stickslip.attach(&mut world.colliders, ch, material);
                    }
                    if let Some(v) = &c.vibration {
                        stickslip.set_vibration(ch, sources[v.as_str()].clone());
                    }
                    colliders.push(SceneCollider {
                        body: body_index,
                        index: j,
                        handle: ch,
                        shape: c.shape.clone(),
                        stickslip: attached,
                        vibration: c.vibration.clone(),
                    });
                }
                bodies.push(SceneBody {
                    name,
                    group: b.name.clone(),
                    handle,
                    kind: b.kind,
                    start,
                });
            }
        }

        let mut drivers = Vec::new();
        for (i, d) in self.drivers.iter().enumerate() {
            let targets: Vec<usize> = bodies
                .iter()
                .enumerate()
                .filter(|(_, b)| b.name == d.body() || b.group == d.body())
                .map(|(k, _)| k)
                .collect();
            for body in targets {
                let mut action = driver_action(i, d)?;
                if let DriverAction::Spring {
                    stiffness,
                    anchor,
                    point,
                    ..
                } = &mut action
                {
                    let rb = &world.bodies[bodies[body].handle];
                    let p0 = rb.position().transform_point(*point);
                    *anchor = [
                        anchor[0] + p0.x as f64,
                        anchor[1] + p0.y as f64,
                        anchor[2] + p0.z as f64,
                    ];
                    let mass = rb.mass() as f64;
                    let w_dt = (*stiffness / mass).sqrt() * self.world.dt;
                    if w_dt.is_nan() || w_dt >= 1.0 {
                        return Err(invalid(
                            format!("driver[{i}].stiffness"),
                            format!(
                                "too stiff for the time step: sqrt(k/m)·dt = {w_dt:.3} must be < 1 \
                                 (m = {mass:.4} kg); lower the stiffness or world.dt"
                            ),
                        ));
                    }
                }
                drivers.push(Driver { body, action });
            }
        }

        Ok(Scene {
            name: self.name.clone(),
            world,
            stickslip,
            bodies,
            colliders,
            drivers,
            steps: self.steps(),
            log_every: self.run.log_every,
            max_contact_series: self.run.max_contact_series,
        })
    }
}

fn profile(field: &str, knots: &[[f64; 2]]) -> Result<ForceProfile, BuildError> {
    ForceProfile::new(
        knots.iter().map(|k| k[0]).collect(),
        knots.iter().map(|k| k[1]).collect(),
    )
    .map_err(|source| BuildError::Param {
        field: field.to_string(),
        source,
    })
}

fn driver_action(i: usize, d: &DriverSpec) -> Result<DriverAction, BuildError> {
    let f = |k: &str| format!("driver[{i}].{k}");
    Ok(match d {
        DriverSpec::Velocity {
            velocity,
            angular,
            start,
            ..
        } => DriverAction::Velocity {
            linear: vec3(*velocity),
            angular: vec3(*angular),
            start: *start,
        },
        DriverSpec::Spring {
            stiffness,
            damping,
            anchor_offset,
            anchor_velocity,
            point,
            axis,
            ..
        } => DriverAction::Spring {
            stiffness: *stiffness,
            damping: *damping,
            // Made absolute by `build` once the body exists.
            anchor: *anchor_offset,
            anchor_velocity: *anchor_velocity,
            point: vec3(*point),
            axis: axis.map(|a| unit(&f("axis"), a)).transpose()?,
        },
        DriverSpec::Force {
            direction,
            knots,
            point,
            ..
        } => DriverAction::Force {
            direction: unit(&f("direction"), *direction)?,
            profile: profile(&f("knots"), knots)?,
            point: point.map(vec3),
        },
    })
}

fn body_builder(b: &BodySpec, start: [f64; 3]) -> RigidBodyBuilder {
    let builder = match b.kind {
        BodyKind::Fixed => RigidBodyBuilder::fixed(),
        BodyKind::Dynamic => RigidBodyBuilder::dynamic(),
        BodyKind::Kinematic => RigidBodyBuilder::kinematic_velocity_based(),
    };
    let builder = builder
        .pose(Pose::from_parts(vec3(start), rotation(b.rotation_deg)))
        .linvel(vec3(b.linvel))
        .angvel(vec3(b.angvel))
        .linear_damping(b.linear_damping as f32)
        .angular_damping(b.angular_damping as f32)
        .can_sleep(b.can_sleep)
        .ccd_enabled(b.ccd);
    if b.lock_rotations {
        builder.lock_rotations()
    } else {
        builder
    }
}

/// rapier's rule for a scenario's.
fn rapier_rule(rule: stickslip_rapier::core::law::CombineRule) -> CoefficientCombineRule {
    use stickslip_rapier::core::law::CombineRule as R;
    match rule {
        R::Average => CoefficientCombineRule::Average,
        R::Min => CoefficientCombineRule::Min,
        R::Multiply => CoefficientCombineRule::Multiply,
        R::Max => CoefficientCombineRule::Max,
        R::ClampedSum => CoefficientCombineRule::ClampedSum,
        R::GeometricMean => CoefficientCombineRule::GeometricMean,
    }
}

fn collider_builder(c: &ColliderSpec) -> ColliderBuilder {
    let builder = match &c.shape {
        ShapeSpec::Cuboid { half_extents: h } => {
            ColliderBuilder::cuboid(h[0] as f32, h[1] as f32, h[2] as f32)
        }
        ShapeSpec::Ball { radius } => ColliderBuilder::ball(*radius as f32),
        ShapeSpec::Capsule {
            half_height,
            radius,
        } => ColliderBuilder::capsule_y(*half_height as f32, *radius as f32),
    };
    let mut builder = builder
        .position(Pose::from_parts(vec3(c.offset), rotation(c.rotation_deg)))
        .friction(c.friction as f32)
        .friction_combine_rule(rapier_rule(c.combine))
        .restitution(c.restitution as f32);
    if let Some(d) = c.density {
        builder = builder.density(d as f32);
    }
    if let Some(m) = c.mass {
        builder = builder.mass(m as f32);
    }
    builder
}
