//! Every CONTACT argument: its range (one failing value each, message asserted), its default,
//! and the combinations the statement forbids.

use super::*;

fn impact() -> ContactArgs {
    ContactArgs {
        impact: true,
        ..ContactArgs::default()
    }
}

fn poisson() -> ContactArgs {
    ContactArgs {
        poisson: true,
        penalty: Some(1e5),
        restitution_coefficient: Some(0.5),
        ..ContactArgs::default()
    }
}

fn err(args: ContactArgs) -> String {
    args.validate(&Units::MMKS).unwrap_err().to_string()
}

#[test]
fn each_argument_rejects_a_value_out_of_its_range() {
    let cases: Vec<(ContactArgs, &str)> = vec![
        (
            ContactArgs {
                stiffness: Some(0.0),
                ..impact()
            },
            "STIFFNESS = 0.0 is out of range: must be finite and > 0",
        ),
        (
            ContactArgs {
                damping: Some(-1.0),
                ..impact()
            },
            "DAMPING = -1.0 is out of range: must be finite and > 0",
        ),
        (
            ContactArgs {
                dmax: Some(0.0),
                ..impact()
            },
            "DMAX = 0.0 is out of range: must be finite and > 0",
        ),
        (
            ContactArgs {
                exponent: Some(-2.0),
                ..impact()
            },
            "EXPONENT = -2.0 is out of range: must be finite and > 0",
        ),
        (
            ContactArgs {
                penalty: Some(-5.0),
                ..poisson()
            },
            "PENALTY = -5.0 is out of range: must be finite and > 0",
        ),
        (
            ContactArgs {
                restitution_coefficient: Some(1.5),
                ..poisson()
            },
            "RESTITUTION_COEFFICIENT = 1.5 is out of range: must be in [0, 1]",
        ),
        (
            ContactArgs {
                coulomb_friction: Some(FrictionSwitch::On),
                mu_static: Some(0.0),
                ..impact()
            },
            "MU_STATIC = 0.0 is out of range: must be finite and > 0",
        ),
        (
            ContactArgs {
                coulomb_friction: Some(FrictionSwitch::On),
                mu_static: Some(0.2),
                mu_dynamic: Some(0.3),
                ..impact()
            },
            "MU_DYNAMIC = 0.3 is out of range: must be in (0, MU_STATIC = 0.2]",
        ),
        (
            ContactArgs {
                coulomb_friction: Some(FrictionSwitch::On),
                stiction_transition_velocity: Some(0.0),
                ..impact()
            },
            "STICTION_TRANSITION_VELOCITY = 0.0 is out of range: must be finite and > 0",
        ),
        (
            ContactArgs {
                coulomb_friction: Some(FrictionSwitch::On),
                stiction_transition_velocity: Some(5.0),
                friction_transition_velocity: Some(5.0),
                ..impact()
            },
            "FRICTION_TRANSITION_VELOCITY = 5.0 is out of range: must be > STICTION_TRANSITION_VELOCITY = 5.0",
        ),
        (
            ContactArgs {
                poisson_transition_velocity: Some(0.0),
                ..poisson()
            },
            "POISSON transition velocity = 0.0 is out of range: must be finite and > 0",
        ),
    ];
    for (args, message) in cases {
        assert_eq!(err(args), message);
    }
}

#[test]
fn forbidden_combinations_are_errors() {
    assert_eq!(
        err(ContactArgs {
            impact: true,
            ..poisson()
        }),
        "IMPACT and POISSON cannot both be given"
    );
    assert_eq!(
        err(ContactArgs {
            augmented_lagrangian: true,
            ..impact()
        }),
        "POISSON is required for AUGMENTED_LAGRANGIAN_FORMULATION (it refines the POISSON model only)"
    );
    assert_eq!(
        err(ContactArgs::default()),
        "IMPACT, POISSON or NORMAL_ROUTINE is required to define the normal force"
    );
    assert_eq!(
        err(ContactArgs {
            poisson: true,
            restitution_coefficient: Some(0.5),
            ..ContactArgs::default()
        }),
        "PENALTY is required with POISSON"
    );
    assert_eq!(
        err(ContactArgs {
            normal_function: Some(vec![1.0]),
            ..ContactArgs::default()
        }),
        "NORMAL_ROUTINE is required with NORMAL_FUNCTION = USER(…) (no default routine is linked)"
    );
    assert_eq!(
        err(ContactArgs {
            normal_routine: Some("libforce".into()),
            ..ContactArgs::default()
        }),
        "NORMAL_ROUTINE = libforce is out of range: must be of the form library::function"
    );
    assert_eq!(
        err(ContactArgs {
            normal_routine: Some("lib::cnf".into()),
            normal_function: Some(vec![0.0; 31]),
            ..ContactArgs::default()
        }),
        "NORMAL_FUNCTION = USER with 31 constants is out of range: must be at most 30 constants"
    );
    assert_eq!(
        err(ContactArgs {
            friction_routine: Some("lib::cff".into()),
            coulomb_friction: Some(FrictionSwitch::On),
            ..impact()
        }),
        "COULOMB_FRICTION and FRICTION_ROUTINE cannot both be given"
    );
}

#[test]
fn defaults_are_adams_views_converted_to_the_model_units() {
    let args = ContactArgs {
        coulomb_friction: Some(FrictionSwitch::DynamicsOnly),
        ..impact()
    };
    let (params, warnings) = args.validate(&Units::MMKS).unwrap();
    let NormalModel::Impact(law) = params.normal else {
        panic!("IMPACT expected")
    };
    assert_eq!(
        (law.stiffness(), law.damping(), law.dmax(), law.exponent()),
        (1e5, 10.0, 0.1, 2.2)
    );
    let FrictionModel::DynamicsOnly(c) = params.friction else {
        panic!("DYNAMICS_ONLY expected")
    };
    assert_eq!(
        (
            c.mu_static(),
            c.mu_dynamic(),
            c.stiction_velocity(),
            c.friction_velocity()
        ),
        (0.3, 0.1, 100.0, 1000.0)
    );
    assert_eq!(warnings.len(), 8, "{warnings:?}");
    // In metres: k × 1000^2.2 (stiffness ∝ length^−e), c × 1000, dmax and velocities / 1000.
    let (params, _) = args.validate(&Units::MKS).unwrap();
    let NormalModel::Impact(law) = params.normal else {
        panic!("IMPACT expected")
    };
    assert!((law.stiffness() / (1e5 * 1000f64.powf(2.2)) - 1.0).abs() < 1e-12);
    assert!((law.damping() - 1e4).abs() < 1e-9);
    assert!((law.dmax() - 1e-4).abs() < 1e-18);
    let FrictionModel::DynamicsOnly(c) = params.friction else {
        panic!("DYNAMICS_ONLY expected")
    };
    assert!(
        (c.stiction_velocity() - 0.1).abs() < 1e-15 && (c.friction_velocity() - 1.0).abs() < 1e-15
    );
}

#[test]
fn a_given_stiffness_uses_the_given_exponent_and_no_default() {
    let args = ContactArgs {
        stiffness: Some(3.0),
        exponent: Some(1.5),
        damping: Some(1.0),
        dmax: Some(0.01),
        ..impact()
    };
    let (params, warnings) = args.validate(&Units::MKS).unwrap();
    assert!(warnings.is_empty());
    let NormalModel::Impact(law) = params.normal else {
        panic!("IMPACT expected")
    };
    assert_eq!(law.stiffness(), 3.0);
}

#[test]
fn stiction_on_and_unused_arguments_are_warnings() {
    let args = ContactArgs {
        stiction: Some(true),
        penalty: Some(1.0),
        mu_static: Some(0.5),
        ..impact()
    };
    let (_, warnings) = args.validate(&Units::MMKS).unwrap();
    assert!(warnings.contains(&ParamWarning::StictionIgnored));
    let text: Vec<String> = warnings.iter().map(|w| w.to_string()).collect();
    assert!(
        text.iter()
            .any(|w| w == "PENALTY has no effect: the normal force model is not POISSON"),
        "{text:?}"
    );
    assert!(
        text.iter()
            .any(|w| w.starts_with("MU_STATIC has no effect")),
        "{text:?}"
    );
}

#[test]
fn poisson_with_augmented_lagrangian_and_user_routines_validate() {
    let (params, _) = ContactArgs {
        augmented_lagrangian: true,
        ..poisson()
    }
    .validate(&Units::MMKS)
    .unwrap();
    assert!(matches!(
        params.normal,
        NormalModel::Poisson {
            augmented_lagrangian: Some(_),
            ..
        }
    ));
    let args = ContactArgs {
        normal_routine: Some("libcontact.so::cnfsub".into()),
        normal_function: Some(vec![1.0, 2.0]),
        friction_routine: Some("libcontact.so::cffsub".into()),
        ..ContactArgs::default()
    };
    let (params, _) = args.validate(&Units::MMKS).unwrap();
    let NormalModel::User(user) = params.normal else {
        panic!("USER expected")
    };
    assert_eq!(
        (
            user.library.as_str(),
            user.function.as_str(),
            user.parameters.len()
        ),
        ("libcontact.so", "cnfsub", 2)
    );
    assert!(matches!(params.friction, FrictionModel::User(_)));
}

#[test]
fn type_and_friction_switch_parse_adams_spellings() {
    for t in ContactType::ALL {
        assert_eq!(ContactType::parse(&t.name().to_uppercase()).unwrap(), t);
    }
    assert!(ContactType::PointToCurve.is_planar() && !ContactType::SphereToPlane.is_planar());
    assert!(
        ContactType::parse("edge_to_edge")
            .unwrap_err()
            .to_string()
            .starts_with("TYPE = edge_to_edge is out of range")
    );
    assert_eq!(
        FrictionSwitch::parse("dynamics_only").unwrap(),
        FrictionSwitch::DynamicsOnly
    );
    assert!(FrictionSwitch::parse("maybe").is_err());
}
