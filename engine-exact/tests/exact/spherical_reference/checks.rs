//! The spherical reference checked against closed forms (the sphere–sphere lens and its
//! affine image) and against the engine where the other references are weakest (a tangency
//! just below the top slice, a sphere through both faces of a flat ellipsoid).

use super::*;

#[test]
fn the_spherical_reference_reproduces_the_lens_and_its_affine_image() {
    use crate::ellipsoid_oracles::{lens_moments, mapped};
    let (c1, c2) = (Vector3::new(0.1, 0.2, -0.1), Vector3::new(0.9, -0.3, 0.4));
    let lens = lens_moments(1.0, &c1, 0.8, &c2).unwrap();
    // Two ellipsoids of one shape: the lens carried by `m`.
    let m = Matrix3::new(1.1, 0.3, -0.2, 0.1, 0.7, 0.25, -0.3, 0.05, 1.4);
    let expected = mapped(&lens, &m, &Vector3::zeros());
    let i = Ellipsoid { c: m * c1, l: m };
    let j = Ellipsoid {
        c: m * c2,
        l: m * 0.8,
    };
    let (got, error, closure) = converged(&i, &j).unwrap();
    assert!(error < 1e-13 && closure < 1e-13, "{error:e} {closure:e}");
    assert!(
        (got.volume - expected.volume).abs() < 1e-13,
        "{got:?} {expected:?}"
    );
    assert!((got.centroid - expected.centroid).norm() < 1e-13);
    assert!((got.area_vector_i - expected.area_vector_i).norm() < 1e-13);
}

/// A sphere against a flattened ellipsoid, sliced along the line of centres: the sections
/// turn tangent 5e-4 of the range below its top, past the last uniform sample of the
/// slicing's shape scan; left inside the last quadrature piece, that kink cost 1.1e-8 in the
/// normal.
#[test]
fn a_tangency_just_below_the_top_slice_is_cut() {
    use crate::common::{errors, instance, one};
    use crate::ellipsoid_oracles::{contact_from, ellipsoid_exit};
    use contact_core::{Geometry, Isometry3};
    use nalgebra::{Quaternion, Translation3, UnitQuaternion};
    let q = |v: [f64; 4]| UnitQuaternion::from_quaternion(Quaternion::new(v[3], v[0], v[1], v[2]));
    let r = 0.964_059_622_428_806_5;
    let semi_j = Vector3::new(
        0.897_122_178_232_636_2,
        1.354_535_625_095_228_3,
        0.536_904_389_767_53,
    );
    let (ri, rj) = (
        q([
            -0.446_954_597_172_452_2,
            -0.245_283_689_092_848_3,
            0.799_456_628_389_456_2,
            -0.317_705_208_102_695_2,
        ]),
        q([
            0.374_008_316_603_169_7,
            0.627_332_356_147_896_8,
            -0.682_263_264_227_285_6,
            0.032_995_944_107_124_41,
        ]),
    );
    let c = Vector3::new(
        -0.116_211_875_023_667_09,
        -1.278_072_820_163_293,
        0.821_613_491_887_674_8,
    );
    let li = ri.to_rotation_matrix().matrix() * r;
    let lj = rj.to_rotation_matrix().matrix() * Matrix3::from_diagonal(&semi_j);
    let (m, error, closure) = converged(
        &Ellipsoid { c, l: li },
        &Ellipsoid {
            c: Vector3::zeros(),
            l: lj,
        },
    )
    .unwrap();
    assert!(error < 1e-12 && closure < 1e-12, "{error:e} {closure:e}");
    let expected = contact_from(
        &m,
        |g, d| ellipsoid_exit(&c, &li, g, d),
        |g, d| ellipsoid_exit(&Vector3::zeros(), &lj, g, d),
    );
    let ellipsoid = |s: Vector3| {
        instance(Geometry::Ellipsoid(
            contact_core::geometry::Ellipsoid::new(s.x, s.y, s.z).unwrap(),
        ))
    };
    let got = one(
        &ellipsoid(Vector3::repeat(r)),
        &ellipsoid(semi_j),
        &Isometry3::from_parts(Translation3::from(c), ri),
        &Isometry3::from_parts(Translation3::identity(), rj),
    );
    let e = errors(&got, &expected, semi_j.max());
    assert!(e.iter().all(|&x| x <= 1e-12), "{e:?}");
}

/// A sphere through both faces of a flattened ellipsoid (radius 0.665, thickness 0.64): each
/// surface's part inside the other is a band, so the rays cross twice and the general path
/// answers. The divergence-theorem oracle is 4e-7 off in volume here; the engine is not.
#[test]
fn a_sphere_through_both_faces_of_a_flat_ellipsoid() {
    use nalgebra::{Quaternion, UnitQuaternion};
    let q = |v: [f64; 4]| UnitQuaternion::from_quaternion(Quaternion::new(v[3], v[0], v[1], v[2]));
    let li = q([
        -0.590_949_067_316_262_4,
        -0.022_105_185_648_148_56,
        0.778_782_140_367_352_7,
        -0.209_258_066_631_481_22,
    ])
    .to_rotation_matrix()
    .matrix()
        * 0.665_017_831_261_324_4;
    let lj = q([
        -0.004_885_980_325_324_807,
        0.266_168_252_118_227_1,
        -0.693_688_725_621_820_4,
        -0.669_273_143_571_265_2,
    ])
    .to_rotation_matrix()
    .matrix()
        * Matrix3::from_diagonal(&Vector3::new(
            0.953_527_315_682_883_2,
            1.151_301_633_642_17,
            0.639_874_740_151_639_6,
        ));
    let c = Vector3::new(
        -0.474_456_740_621_059_97,
        0.064_510_263_865_496_59,
        -0.075_745_817_384_279_99,
    );
    let (i, j) = (
        Ellipsoid { c, l: li },
        Ellipsoid {
            c: Vector3::zeros(),
            l: lj,
        },
    );
    let (coarse, _) = moments(&i, &j, 2048).unwrap();
    let (m, closure) = moments(&i, &j, 4096).unwrap();
    let error = (m.volume - coarse.volume)
        .abs()
        .max((m.area_vector_i - coarse.area_vector_i).norm());
    assert!(error < 1e-13 && closure < 1e-13, "{error:e} {closure:e}");
    use crate::common::{errors, instance, one};
    use crate::ellipsoid_oracles::{contact_from, ellipsoid_exit};
    use contact_core::{Geometry, Isometry3};
    use nalgebra::Translation3;
    let expected = contact_from(
        &m,
        |g, d| ellipsoid_exit(&c, &li, g, d),
        |g, d| ellipsoid_exit(&Vector3::zeros(), &lj, g, d),
    );
    let ellipsoid = |s: Vector3| {
        instance(Geometry::Ellipsoid(
            contact_core::geometry::Ellipsoid::new(s.x, s.y, s.z).unwrap(),
        ))
    };
    let got = one(
        &ellipsoid(Vector3::repeat(0.665_017_831_261_324_4)),
        &ellipsoid(Vector3::new(
            0.953_527_315_682_883_2,
            1.151_301_633_642_17,
            0.639_874_740_151_639_6,
        )),
        &Isometry3::from_parts(
            Translation3::from(c),
            q([
                -0.590_949_067_316_262_4,
                -0.022_105_185_648_148_56,
                0.778_782_140_367_352_7,
                -0.209_258_066_631_481_22,
            ]),
        ),
        &Isometry3::from_parts(
            Translation3::identity(),
            q([
                -0.004_885_980_325_324_807,
                0.266_168_252_118_227_1,
                -0.693_688_725_621_820_4,
                -0.669_273_143_571_265_2,
            ]),
        ),
    );
    let e = errors(&got, &expected, 1.151_301_633_642_17);
    assert!(e.iter().all(|&x| x <= 1e-12), "{e:?}");
}
