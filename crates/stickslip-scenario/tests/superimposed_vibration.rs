//! Scenario files describe superimposed vibration (Popov's Eq. 9) as `components = [..]` of a
//! `[vibration.NAME]` table. Invariants: the file builds the same source as the API
//! (`VibrationSource::superimposed` with the same components, frequency and mode); a
//! one-component file (the inline form) is unchanged; giving both forms, neither, a bad
//! component or two of one kind is a typed error naming the field. (What such a source does
//! in a run — sleds driven at Popov's free drive velocity — is checked on the shipped
//! `scenarios/elliptical_drive.toml` in `shipped_scenarios.rs`.)

use stickslip_core::waveform::Waveform;
use stickslip_rapier::{
    Amplitude, VibrationComponent, VibrationDirection, VibrationMode, VibrationSource,
};
use stickslip_scenario::{Scenario, Scene};

/// `VibratingPlate::elliptical(0.6, 0.75, shift)` as a file: a 100 kg sled (0.2 m, rotations
/// locked) pressed by 9.81 N onto a fixed plate (EP, c = 1e4, μ_ba = μ_max = 0.5), the plate
/// vibrating at 50 Hz normal (ratio 0.6) and along x (ratio 0.75) `shift` periods later,
/// time-resolved at 400 steps a period. `components` replaces the source's component lines.
fn plate(shift: f64, components: &str) -> String {
    format!(
        r#"name = "ellipse"
[world]
dt = 5e-5
gravity = [0.0, -0.0981, 0.0]
[run]
steps = 10
[material.ep]
law = "ep"
c = 1e4
mu_ba = 0.5
mu_max = 0.5
curve = {{ kind = "constant", mu = 0.5 }}
[vibration.ellipse]
frequency = 50.0
{components}
[[body]]
name = "plate"
kind = "fixed"
position = [0.0, -0.1, 0.0]
[[body.collider]]
shape = {{ kind = "cuboid", half_extents = [50.0, 0.1, 2.0] }}
material = "ep"
vibration = "ellipse"
[[body]]
name = "sled"
position = [0.0, 0.1, 0.0]
can_sleep = false
lock_rotations = true
[[body.collider]]
shape = {{ kind = "cuboid", half_extents = [0.1, 0.1, 0.1] }}
mass = 100.0
"#
    )
    .replace("SHIFT", &shift.to_string())
}

const ELLIPSE: &str = r#"components = [
  { direction = { kind = "normal" }, amplitude = { ratio = 0.6 } },
  { direction = { kind = "tangential", axis = [1.0, 0.0, 0.0] }, amplitude = { ratio = 0.75 }, phase = SHIFT },
]"#;

/// Two component lists are the same (waveforms compared by their debug form: the built-in
/// ones carry no closure).
fn same(a: &[VibrationComponent], b: &[VibrationComponent]) -> bool {
    a.len() == b.len()
        && a.iter().zip(b).all(|(a, b)| {
            a.direction() == b.direction()
                && a.amplitude() == b.amplitude()
                && a.phase() == b.phase()
                && format!("{:?}", a.waveform()) == format!("{:?}", b.waveform())
        })
}

fn scene_of(text: &str) -> Scene {
    Scenario::from_toml_str(text).unwrap().build().unwrap()
}

fn source_of(text: &str) -> VibrationSource {
    let scene = scene_of(text);
    let plate = scene.colliders[0].handle;
    scene.stickslip.vibration(plate).expect("a source").clone()
}

#[test]
fn components_build_the_apis_superimposed_source() {
    let s = source_of(&plate(0.25, ELLIPSE));
    let want = VibrationSource::superimposed(
        &[
            VibrationComponent::new(
                VibrationDirection::Normal,
                Amplitude::Ratio(0.6),
                Waveform::Sine,
                0.0,
            )
            .unwrap(),
            VibrationComponent::new(
                VibrationDirection::Tangential {
                    axis: [1.0, 0.0, 0.0],
                },
                Amplitude::Ratio(0.75),
                Waveform::Sine,
                0.25,
            )
            .unwrap(),
        ],
        50.0,
        VibrationMode::TimeResolved,
    )
    .unwrap();
    assert!(same(s.components(), want.components()));
    assert_eq!(s.frequency(), want.frequency());
    assert_eq!(s.mode(), want.mode());
    // The inline form still gives a one-component source.
    let inline = source_of(&plate(
        0.0,
        r#"direction = { kind = "normal" }
amplitude = { ratio = 0.5 }
waveform = { kind = "square" }
phase = 0.1"#,
    ));
    let want = VibrationComponent::new(
        VibrationDirection::Normal,
        Amplitude::Ratio(0.5),
        Waveform::Square,
        0.1,
    )
    .unwrap();
    assert!(same(inline.components(), &[want]));
}

#[test]
fn malformed_component_lists_name_the_field() {
    let field_of = |text: &str| -> Option<String> {
        match Scenario::from_toml_str(text) {
            Err(e) => e.field().map(str::to_string),
            Ok(s) => Some(
                s.build()
                    .map(|_| ())
                    .expect_err("rejected")
                    .field()
                    .to_string(),
            ),
        }
    };
    // Both forms at once.
    let both = plate(
        0.25,
        &format!("direction = {{ kind = \"normal\" }}\n{ELLIPSE}"),
    );
    assert_eq!(
        field_of(&both).as_deref(),
        Some("vibration.ellipse.components")
    );
    // Neither.
    assert_eq!(
        field_of(&plate(0.0, "")).as_deref(),
        Some("vibration.ellipse.direction")
    );
    // A component with a negative amplitude.
    let bad = ELLIPSE.replace("ratio = 0.75", "ratio = -0.75");
    assert_eq!(
        field_of(&plate(0.25, &bad)).as_deref(),
        Some("vibration.ellipse.components[1]")
    );
    // Two normal components: the source's own check, at the table.
    let twice = ELLIPSE.replace(
        "kind = \"tangential\", axis = [1.0, 0.0, 0.0]",
        "kind = \"normal\"",
    );
    assert_eq!(
        field_of(&plate(0.25, &twice)).as_deref(),
        Some("vibration.ellipse")
    );
}
