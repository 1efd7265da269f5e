//! A short tour of `ga::g3`: products of the report's basis, a rotation, and the report's
//! ray-tracing geometry (plane from a triangle, line-plane intersection, point in triangle).
//!
//! Run with `cargo run -p ga --example tour`.

use std::f64::consts::FRAC_PI_2;

use ga::g3::geometry::{Line, Plane, point_in_triangle};
use ga::g3::{Bivector, Multivector, Rotor, Vector};

fn main() {
    println!("== Products of basis blades (report section 2.2)");
    let (e1, e2, e3) = (Multivector::<f64>::E1, Multivector::E2, Multivector::E3);
    println!("e1 e2           = {}", e1 * e2);
    println!("e2 e1           = {}", e2 * e1);
    println!("e1 e1           = {}", e1 * e1);
    println!("(e1^e2)(e1^e2^e3) = {}", (e1 ^ e2) * (e1 ^ e2 ^ e3));
    println!("e1 | e12        = {}", e1 | Multivector::E12);
    println!(
        "e12 | e12       = {}   (the report's inner product: same orientation is negative)",
        Multivector::<f64>::E12 | Multivector::E12
    );
    println!(
        "e12 & e23       = {}   (regressive product: two planes meet in a line)",
        Multivector::<f64>::E12 & Multivector::E23
    );

    println!("\n== Vectors");
    let a = Vector::new(1.0, 2.0, 0.5);
    let b = Vector::new(-0.5, 1.0, 2.0);
    println!("a = {a}, b = {b}");
    println!("a b = a | b + a ^ b = {}", a * b);
    println!("a | b = {}", a | b);
    println!("a ^ b = {}   (its dual is a x b = {})", a ^ b, (a ^ b).dual());
    let plane = Bivector::E12;
    println!("projection of a on e12 = {}, rejection = {}", a.project(plane), a.reject(plane));

    println!("\n== A general multivector and its inverse (closed form)");
    let m = Multivector::new(1.0, 2.0, 0.0, 0.0, 0.0, -0.5, 0.0, 0.25);
    let inv = m.inverse().expect("invertible");
    println!("m       = {m}");
    println!("m^-1    = {inv:.4}");
    println!("m m^-1  = {:.3}", m * inv);
    println!("1 + e1 has an inverse: {}", (Multivector::<f64>::ONE + e1).inverse().is_some());

    println!("\n== Rotation: R = exp(-B theta/2), x' = R x R~");
    let r = Rotor::from_angle_plane(FRAC_PI_2, Bivector::E12);
    println!("R (90 degrees in e12) = {r:.4}");
    println!("R e1 R~ = {:.3}", r.rotate(Vector::E1));
    let to = Rotor::from_vectors(Vector::E1, Vector::new(0.0, 0.0, -3.0));
    println!("rotor taking e1 to -e3: {to:.4}; applied to e1: {:.3}", to.rotate(Vector::E1));

    println!("\n== Report section 3: a triangle, its plane, and a line through it");
    let (ta, tb, tc) =
        (Vector::new(-1.0, -1.0, 4.0), Vector::new(1.0, -1.0, 4.0), Vector::new(0.0, 1.0, 4.0));
    let plane = Plane::from_triangle(ta, tb, tc);
    println!("triangle {ta} / {tb} / {tc}");
    println!(
        "plane: B = {}, normal B* = {}, signed offset d = {}",
        plane.bivector,
        plane.normal(),
        plane.offset
    );
    let line = Line::new(Vector::new(0.1, -0.2, 0.0), Vector::new(0.0, 0.0, 1.0));
    match plane.intersect_line(&line) {
        Some((t, p)) => {
            println!("line {} + t {} meets it at t = {t}, p = {p}", line.point, line.dir);
            println!("p inside the triangle: {}", point_in_triangle(p, ta, tb, tc));
        }
        None => println!("line is parallel to the plane"),
    }
    let miss = Line::new(Vector::new(3.0, 0.0, 0.0), Vector::new(0.0, 0.0, 1.0));
    let (_, q) = plane.intersect_line(&miss).expect("not parallel");
    println!(
        "line through (3, 0, 0) meets the plane at {q}, inside: {}",
        point_in_triangle(q, ta, tb, tc)
    );
    let behind = Plane::from_triangle(-ta, -tb, -tc);
    println!(
        "the mirrored triangle behind the origin has offset {} \
         (the report's |a_perp| would say {})",
        behind.offset,
        (-ta).reject(behind.bivector).norm()
    );
}
