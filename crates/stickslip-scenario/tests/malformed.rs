//! Malformed scenario files are rejected with a typed error that names the offending field
//! (as a dotted path like `body[1].collider[0].density`) and, for anything the TOML parser
//! sees, the 1-based line of the offending key or value; validation errors (NaN, negative
//! sizes, unknown references, too-stiff springs) name the field too. Counts, sizes and
//! magnitudes beyond `stickslip_scenario::limits` (a `repeat.count` of 1e9, 1e9 solver
//! iterations, runs of 1e18 steps, numbers that overflow or underflow rapier's f32) are
//! validation errors with field and line, found without allocating by the count. An empty
//! scenario name is a validation error naming `name`. Loading or
//! building never panics, even on every truncation of every shipped scenario.

use stickslip_scenario::limits::*;
use stickslip_scenario::{BuildError, Scenario, ScenarioError};

const BASE: &str = r#"name = "t"
[world]
dt = 0.01
[material.ep]
law = "ep"
c = 1e4
mu_ba = 0.3
mu_max = 0.32
curve = { kind = "constant", mu = 0.32 }
[[body]]
name = "ground"
kind = "fixed"
[[body.collider]]
shape = { kind = "cuboid", half_extents = [5.0, 0.1, 5.0] }
material = "ep"
[[body]]
name = "block"
position = [0.0, 0.15, 0.0]
[[body.collider]]
shape = { kind = "cuboid", half_extents = [0.05, 0.05, 0.05] }
density = 1000.0
"#;

/// `BASE` with line `line` (1-based) replaced by `with`.
fn replace_line(line: usize, with: &str) -> String {
    BASE.lines()
        .enumerate()
        .map(|(i, l)| if i + 1 == line { with } else { l })
        .collect::<Vec<_>>()
        .join("\n")
}

fn err(text: &str) -> ScenarioError {
    match Scenario::from_toml_str(text) {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(e) => {
            println!("--- error ---\n{e}");
            e
        }
    }
}

#[test]
fn base_is_valid() {
    let s = Scenario::from_toml_str(BASE).unwrap();
    assert_eq!(s.bodies.len(), 2);
    s.build().unwrap();
}

#[test]
fn misspelled_key_names_field_and_line() {
    let e = err(&replace_line(21, "densty = 1000.0"));
    assert!(
        e.field()
            .is_some_and(|f| f.starts_with("body[1].collider[0]")),
        "{:?}",
        e.field()
    );
    assert_eq!(e.line(), Some(21));
    let msg = e.to_string();
    assert!(msg.contains("densty"), "{msg}");
    assert!(msg.contains("<string>:21"), "{msg}");
}

#[test]
fn wrong_type_names_field_and_line() {
    let e = err(&replace_line(18, "position = [0.0, \"up\", 0.0]"));
    assert_eq!(e.field(), Some("body[1].position[1]"));
    assert_eq!(e.line(), Some(18));

    let e = err(&replace_line(3, "dt = \"fast\""));
    assert_eq!(e.field(), Some("world.dt"));
    assert_eq!(e.line(), Some(3));
    assert!(
        e.to_string().contains("dt = \"fast\""),
        "the source line is quoted"
    );
}

#[test]
fn unknown_enum_value_names_field_and_line() {
    let e = err(&replace_line(12, "kind = \"floating\""));
    assert_eq!(e.field(), Some("body[0].kind"));
    assert_eq!(e.line(), Some(12));
    assert!(e.to_string().contains("floating"));
}

#[test]
fn syntax_error_has_line() {
    let e = err(&replace_line(7, "mu_ba = [0.3"));
    assert!(matches!(e, ScenarioError::Parse(_)));
    assert!(matches!(e.line(), Some(7) | Some(8)), "{:?}", e.line());
}

#[test]
fn invalid_law_parameters_name_the_material() {
    // μ_ba above μ_max: the core's validation, reported at the material.
    let e = err(&replace_line(7, "mu_ba = 0.5"));
    assert!(
        e.field().is_some_and(|f| f.starts_with("material.ep")),
        "{:?}",
        e.field()
    );
    assert!(e.to_string().contains("mu_ba"), "{e}");
    assert!(e.line().is_some());
}

#[test]
fn nan_and_negative_sizes_are_typed_validation_errors() {
    let e = err(&replace_line(21, "density = nan"));
    match e.build_error() {
        Some(BuildError::InvalidValue { field, .. }) => {
            assert_eq!(field, "body[1].collider[0].density")
        }
        other => panic!("{other:?}"),
    }
    // Validation errors are located too.
    assert_eq!(e.line(), Some(21));
    assert!(
        e.to_string()
            .starts_with("<string>:21: field `body[1].collider[0].density`")
    );
    let e = err(&replace_line(
        20,
        "shape = { kind = \"cuboid\", half_extents = [0.05, -0.05, 0.05] }",
    ));
    assert_eq!(e.field(), Some("body[1].collider[0].shape.half_extents[1]"));
    assert_eq!(e.line(), Some(20));
    let e = err(&replace_line(3, "dt = -0.01"));
    assert_eq!(e.field(), Some("world.dt"));
    let e = err(&replace_line(3, "dt = inf"));
    assert_eq!(e.field(), Some("world.dt"));
}

#[test]
fn an_empty_name_is_a_typed_error_naming_the_field() {
    // Not rerun's "invalid application id" at run time: the scenario names the field.
    for name in ["name = \"\"", "name = \"   \""] {
        let e = err(&replace_line(1, name));
        assert_eq!(e.field(), Some("name"), "{e}");
        assert_eq!(e.line(), Some(1));
    }
}

#[test]
fn unknown_references_are_typed() {
    let e = err(&format!(
        "{BASE}[[driver]]\nkind = \"force\"\nbody = \"blok\"\ndirection = [1.0, 0.0, 0.0]\nknots = [[0.0, 0.0], [1.0, 1.0]]\n"
    ));
    match e.build_error() {
        Some(BuildError::Unknown {
            field,
            what,
            name,
            known,
        }) => {
            assert_eq!(field, "driver[0].body");
            assert_eq!(e.line(), Some(24));
            assert_eq!(*what, "body");
            assert_eq!(name, "blok");
            assert!(known.contains(&"block".to_string()));
        }
        other => panic!("{other:?}"),
    }
    let e = err(&replace_line(15, "material = \"rubber\""));
    assert_eq!(e.field(), Some("body[0].collider[0].material"));
    let e = err(&format!("{BASE}vibration = \"shaker\"\n"));
    assert_eq!(e.field(), Some("body[1].collider[0].vibration"));
}

#[test]
fn driver_errors_are_typed() {
    // A force driver on a fixed body.
    let e = err(&format!(
        "{BASE}[[driver]]\nkind = \"force\"\nbody = \"ground\"\ndirection = [1.0, 0.0, 0.0]\nknots = [[0.0, 0.0], [1.0, 1.0]]\n"
    ));
    assert!(matches!(
        e.build_error(),
        Some(BuildError::WrongBodyKind { .. })
    ));
    // Knots not starting at 0.
    let e = err(&format!(
        "{BASE}[[driver]]\nkind = \"force\"\nbody = \"block\"\ndirection = [1.0, 0.0, 0.0]\nknots = [[0.5, 0.0], [1.0, 1.0]]\n"
    ));
    assert_eq!(e.field(), Some("driver[0].knots"));
    // Zero direction.
    let e = err(&format!(
        "{BASE}[[driver]]\nkind = \"force\"\nbody = \"block\"\ndirection = [0.0, 0.0, 0.0]\nknots = [[0.0, 0.0], [1.0, 1.0]]\n"
    ));
    assert_eq!(e.field(), Some("driver[0].direction"));
    // Unknown driver kind: a parse error at the driver, with its line.
    let e = err(&format!(
        "{BASE}[[driver]]\nkind = \"magnet\"\nbody = \"block\"\n"
    ));
    assert_eq!(e.field(), Some("driver[0].kind"));
    assert!(e.line().is_some_and(|l| l >= 22), "{:?}", e.line());
}

#[test]
fn too_stiff_spring_is_rejected_at_build() {
    // m = 1 kg, dt = 0.01 s: sqrt(k/m)·dt < 1 needs k < 1e4 N/m.
    let text = format!("{BASE}[[driver]]\nkind = \"spring\"\nbody = \"block\"\nstiffness = 1e5\n");
    // The mass is known once the world is built: `build` rejects it, typed.
    let e = Scenario::from_toml_str(&text)
        .unwrap()
        .build()
        .err()
        .unwrap();
    println!("{e}");
    assert!(matches!(e, BuildError::InvalidValue { .. }));
    assert_eq!(e.field(), "driver[0].stiffness");
    let ok = format!("{BASE}[[driver]]\nkind = \"spring\"\nbody = \"block\"\nstiffness = 1e3\n");
    Scenario::from_toml_str(&ok).unwrap().build().unwrap();
}

#[test]
fn duplicate_and_malformed_names() {
    let e = err(&replace_line(17, "name = \"ground\""));
    assert!(matches!(
        e.build_error(),
        Some(BuildError::DuplicateBody { .. })
    ));
    let e = err(&replace_line(17, "name = \"my block\""));
    assert_eq!(e.field(), Some("body[1].name"));
    let e = err(
        "name = \"t\"\n[run]\nsteps = 10\nduration = 1.0\n[[body]]\nname = \"a\"\nkind = \"fixed\"\n",
    );
    assert_eq!(e.field(), Some("run"));
}

#[test]
fn io_error_names_the_path() {
    let e = Scenario::from_path("/nonexistent/scenario.toml").unwrap_err();
    assert!(matches!(e, ScenarioError::Io { .. }));
    assert!(e.to_string().contains("/nonexistent/scenario.toml"));
}

#[test]
fn no_truncation_of_a_shipped_scenario_panics() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenarios");
    let mut checked = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        for n in 0..=lines.len() {
            let prefix = lines[..n].join("\n");
            // Either outcome is fine; a panic fails the test.
            if let Ok(s) = Scenario::from_toml_str(&prefix) {
                let _ = s.build();
            }
            checked += 1;
        }
    }
    assert!(checked > 100, "checked {checked} prefixes");
}

#[test]
fn counts_beyond_the_machine_are_refused_before_allocating() {
    // A billion repeated blocks: refused at once (a name per copy would take tens of GB).
    let start = std::time::Instant::now();
    let repeat = |n: u64| {
        replace_line(
            18,
            &format!(
                "position = [0.0, 0.15, 0.0]\nrepeat = {{ count = {n}, offset = [0.2, 0.0, 0.0] }}"
            ),
        )
    };
    let e = err(&repeat(1_000_000_000));
    assert_eq!(e.field(), Some("body[1].repeat.count"));
    assert_eq!(e.line(), Some(19));
    assert!(e.to_string().contains(&MAX_BODIES.to_string()), "{e}");
    assert!(
        start.elapsed().as_secs() < 10,
        "validation must not loop over the count"
    );
    // Fine one by one, too many together.
    let many = repeat(60_000);
    let second =
        many[many.find("[[body]]\nname = \"block\"").unwrap()..].replace("\"block\"", "\"block2\"");
    let e = err(&format!("{many}\n{second}"));
    assert_eq!(e.field(), Some("body[2]"));

    let e = err(&replace_line(
        3,
        "dt = 0.01\nsolver_iterations = 1000000000",
    ));
    assert_eq!(e.field(), Some("world.solver_iterations"));
    assert_eq!(e.line(), Some(4));
    let e = err(&format!("{BASE}[run]\nsteps = 1000000000000000000\n"));
    assert_eq!(e.field(), Some("run.steps"));
    // duration/dt beyond u64 must not wrap around into a short run.
    let e = err(&format!("{BASE}[run]\nduration = 1e300\n"));
    assert_eq!(e.field(), Some("run.duration"));
    // Each count fine alone, their product too much work.
    let e = err(&format!("{}\n[run]\nsteps = 10000000\n", repeat(50_000)));
    assert_eq!(e.field(), Some("run.steps"));
    assert!(e.to_string().contains("exceeds"), "{e}");
    let e = err(&format!("{BASE}[run]\nmax_contact_series = 1000000000\n"));
    assert_eq!(e.field(), Some("run.max_contact_series"));
}

#[test]
fn numbers_beyond_rapiers_f32_are_refused_with_field_and_line() {
    // (line, replacement, field): overflow in f32, underflow to zero, tiny time steps.
    let cases = [
        (18, "position = [1e39, 0.15, 0.0]", "body[1].position[0]"),
        (18, "position = [0.0, 1e13, 0.0]", "body[1].position[1]"),
        (21, "density = 1e39", "body[1].collider[0].density"),
        (21, "density = 1e-50", "body[1].collider[0].density"),
        (21, "mass = 1e-300", "body[1].collider[0].mass"),
        (
            20,
            "shape = { kind = \"cuboid\", half_extents = [1e-50, 0.05, 0.05] }",
            "body[1].collider[0].shape.half_extents[0]",
        ),
        (
            20,
            "shape = { kind = \"ball\", radius = 1e40 }",
            "body[1].collider[0].shape.radius",
        ),
        (3, "dt = 1e-30", "world.dt"),
        (3, "dt = 100.0", "world.dt"),
        (
            2,
            "[world]\ngravity = [0.0, -1e39, 0.0]",
            "world.gravity[1]",
        ),
    ];
    for (line, with, field) in cases {
        let e = err(&replace_line(line, with));
        assert_eq!(e.field(), Some(field), "{with}");
        assert!(e.line().is_some(), "{with}: {e}");
        assert!(e.build_error().is_some(), "{with}: a validation error, {e}");
    }
    // The limits themselves are accepted.
    let ok = replace_line(21, &format!("density = {MAX_MAGNITUDE:e}"));
    Scenario::from_toml_str(&ok).unwrap();
}
