//! Errata in the report this project starts from (T. Chauncey, *An Investigation into Geometric
//! Algebra & its Implementation in a Ray Tracer*).
//!
//! This module holds no code: it records, once, where the report is wrong and what this crate
//! does instead, so that a reader who follows the report and gets a different answer from
//! [`crate::g3`] knows which one to trust. Each entry quotes the report, says what is right and
//! why, and names the test in `crates/ga/tests/` that demonstrates it. The tests compute the
//! report's version and the corrected version side by side (with the `ga-reference` crate, the
//! generic algebra, or with [`crate::g3`]) and assert that they differ as described, so an
//! entry here cannot silently become untrue.
//!
//! Notation: `e1, e2, e3` are orthonormal, `e12 = e1 e2`, `e23 = e2 e3`, `e31 = e3 e1`,
//! `I = e123 = e1 e2 e3`, `|` is the report's inner product (the grade `|r - s|` part, zero
//! when either side is a scalar), `*` after a quantity is the dual `A I^-1`.
//!
//! # E1. The three multiplication tables are transposed (figures 2.5, 2.6, 2.7)
//!
//! *Report:* the tables are introduced as the products "between two multivectors", with the
//! left factor down the rows and the right factor across the columns; row `e1`, column `e2` of
//! figure 2.5 reads `(-e12)`.
//!
//! *Right:* `e1 e2 = +e12` by the report's own equation 2.11. Every one of the 3 x 64 printed
//! entries equals `column * row`, not `row * column`: the tables are correct once transposed.
//! Read as printed, 24 entries of figure 2.5, 6 of figure 2.6 and 12 of figure 2.7 have the
//! wrong sign (exactly the pairs of blades that anticommute). A program built from the tables
//! as printed computes `B A` where it should compute `A B`, which for rotors composes rotations
//! in the wrong order.
//!
//! *Tests:* `report_tables.rs` holds the three tables as printed and checks all 192 entries
//! against both readings and against [`crate::g3`]; `errata.rs::e1_tables_are_transposed`.
//!
//! # E2. The plane's bivector is written `a' ^ c'` (section 3.1)
//!
//! *Report:* "We can now describe the orientation of the plane by calculating the outer
//! product between **b'** and **c'** ... `B = a' ^ c'`".
//!
//! *Right:* `B = b' ^ c' = (b - a) ^ (c - a)`, as the sentence says. The formula as printed is
//! always zero, because `a' = a - a = 0`.
//!
//! *Test:* `errata.rs::e2_plane_bivector_from_a_prime_is_zero`.
//!
//! # E3. The plane offset loses its sign (sections 2.4.2, 3.1, 4.2)
//!
//! *Report:* the plane is a bivector `B` and "its perpendicular distance from the origin",
//! computed as `d = |a_perp B|`, the length of the rejection of a vertex from `B`; section 4.2
//! stores "the magnitude of the perpendicular distance".
//!
//! *Right:* the line-plane formula of section 3.2 describes the plane `x . n = d` with
//! `n = B*`, so `d` must be the signed offset `a . n = (a ^ B)*` (for unit `B`). A length is
//! never negative, so every plane with the origin on its positive side (`a . n < 0`) is
//! reflected through the origin: rays hit a plane at the wrong place, or miss it. This crate's
//! planes store the signed offset.
//!
//! *Test:* `errata.rs::e3_unsigned_offset_puts_the_plane_on_the_wrong_side`.
//!
//! # E4. The intersection formula needs a unit bivector, which section 3.1 never makes (3.1, 3.2)
//!
//! *Report:* `p_i = a - ((a ^ B)* - d) u / (u ^ B)*` with `B = b' ^ c'` and `d` a distance.
//!
//! *Right:* `(a ^ B)*` and `(u ^ B)*` both scale with `|B|` but `d` does not, so the formula
//! holds only when `|B| = 1` (or when `d` is measured in units of `|B|`, i.e. `d = (a ^ B)*`).
//! `b' ^ c'` has magnitude twice the triangle's area, so the report's own planes give wrong
//! intersection points for every triangle whose area is not 1/2 and whose plane misses the
//! origin. Normalise `B`, or keep `d = (a ^ B)*` unnormalised as this crate can.
//!
//! *Test:* `errata.rs::e4_intersection_needs_a_unit_bivector`.
//!
//! # E5. `A† A` is not a scalar for a general multivector (section 2.3.2)
//!
//! *Report:* "`A† A` will always produce a scalar that is equal to the sum of the square of
//! the coefficients", and "Not all multivectors have an inverse. Fortunately, there are a
//! particular set which do, known as versors."
//!
//! *Right:* only the scalar part of `A† A` is the sum of squared coefficients. For
//! `A = 1 + e1`, `A† A = 2 + 2 e1`; for `A = 2 + e1`, `A† A = 5 + 4 e1`. So `A† / (A† A)` is
//! the inverse of versors only. Non-versors can be invertible too: `2 + e1` is not a versor
//! (it mixes even and odd grades) yet `(2 + e1)(2 - e1) / 3 = 1`. In G3 the general inverse
//! uses the Clifford conjugate `Ā` instead: `A Ā = alpha + beta I` lies in the centre
//! `span{1, I}` (it behaves as a complex number), and `A^-1 = Ā (alpha - beta I) /
//! (alpha^2 + beta^2)`, which exists exactly when `alpha^2 + beta^2 != 0`. `1 + e1` is a zero
//! divisor, `(1 + e1)(1 - e1) = 0`, and has no inverse at all.
//!
//! *Tests:* `errata.rs::e5_reverse_product_is_not_scalar_in_general`, and
//! `properties.rs` (inverse exists exactly when `A Ā` is non-zero).
//!
//! # E6. The sum of squares is written as a sum (section 2.3.2)
//!
//! *Report:* `A† A = sum_{k=1}^{n} a_k`, "where a is the coefficient of the component".
//!
//! *Right:* `sum a_k^2`, as the sentence before it says (and only for versors, see E5).
//!
//! *Test:* `errata.rs::e6_reverse_product_of_a_versor_is_the_sum_of_squares`.
//!
//! # E7. The point-in-triangle sign test is inverted (section 3.3)
//!
//! *Report:* "`A = ab ^ ap`, `B = ab ^ ac`, `s = A . B`. If s is positive, the orientation of
//! both bivectors are the same ... p therefore lies on the correct side of the edge."
//!
//! *Right:* with the report's own inner product (figure 2.7: `e12 . e12 = -1`, since
//! `e12 e12 = -1`), two bivectors of the same orientation give a *negative* scalar: for
//! `A = alpha N`, `B = beta N` with a unit bivector `N`, `A . B = -alpha beta`. As written, the
//! test rejects every point inside the triangle; since it accepts a point only when all three
//! `s` are positive, i.e. when the point lies outside all three edges, which no point does, it
//! accepts nothing at all. Compare with `-(A . B)`, with the scalar product `<A B†>_0` (the sum
//! of coefficient products), or compare the duals `A*` and `B*` (the triangle normals) with a
//! vector dot product; `ga::g3::geometry::point_in_triangle` accepts `s <= 0`.
//!
//! *Test:* `errata.rs::e7_report_sign_rule_accepts_no_point`.
//!
//! # E8. "If they are parallel, the dot product is 1" (section 2.2.1)
//!
//! *Right:* only for parallel *unit* vectors. In general `a . b = |a| |b| cos(theta)`: `|a| |b|`
//! for parallel vectors and `-|a| |b|` for antiparallel ones. The same slip recurs in 2.2.3
//! ("the inner product between these is equal to 1").
//!
//! *Test:* `errata.rs::e8_parallel_vectors_dot_to_the_product_of_lengths`.
//!
//! # E9. "The magnitude of c is equal to the magnitude of b" (section 2.2.1)
//!
//! *Report:* for a bivector `A` and a vector `b` in its plane, `c = A . b` has the magnitude of
//! `b`.
//!
//! *Right:* `|c| = |A| |b|`; the claim holds only for a unit bivector.
//!
//! *Test:* `errata.rs::e9_bivector_vector_inner_product_scales_with_the_bivector`.
//!
//! # E10. The inner product of two scalars (section 2.2.1 against figure 2.7)
//!
//! *Report:* "The inner product between two scalars is simply the scalar product", but row and
//! column `s` of figure 2.7 are all zero, `s . s` included.
//!
//! *Right:* the two statements contradict each other. The table's rule (the inner product
//! vanishes when either side is a scalar, Hestenes' convention) is the one that makes the
//! report's later formulas work, so this crate's `|` follows the table; the product of scalars
//! is available as the scalar product and as the left contraction.
//!
//! *Test:* `errata.rs::e10_scalar_inner_scalar_is_zero_in_the_table`.
//!
//! # E11. The inner product with the trivector gives the negative normal (section 2.2.1)
//!
//! *Report (2.2.1):* "if we wish to find the normal to a bivector, we simply find its inner
//! product with the base trivector."
//!
//! *Right:* `I . e12 = -e3`, the negative of the right-handed normal `e1 x e2 = e3`. The report
//! corrects itself in 2.3.3 ("This is in fact the negative normal ... Using the dual solves this
//! problem") and that correction is right: `e12* = e12 I^-1 = +e3`. Recorded so that a reader of
//! 2.2.1 alone is not misled.
//!
//! *Test:* `errata.rs::e11_trivector_inner_bivector_is_the_negative_normal`.
//!
//! # E12. The rules said to derive the inner product table do not (section 2.2.3)
//!
//! *Report:* rule 2: "If two terms contain similar components, the inner product between these
//! is equal to 1 and so the result is included."
//!
//! *Right:* `e12` and `e23` share `e2`, yet figure 2.7 (correctly) has 0 there, and
//! `e12 . e12 = -1`, not 1. The rule that produces the table is a grade selection: keep the
//! grade `|r - s|` part of the geometric product of an `r`-blade and an `s`-blade (zero when
//! either grade is 0). `e12 e23 = e13` has grade 2, not 0, so `e12 . e23 = 0`.
//!
//! *Test:* `errata.rs::e12_shared_components_do_not_decide_the_inner_product`.
//!
//! # E13. "Linearly dependant vectors" span a trivector (section 2.1.2)
//!
//! *Right:* linearly *independent*. For dependent vectors `a ^ b ^ c = 0`.
//!
//! *Test:* `errata.rs::e13_dependent_vectors_span_no_volume`.
//!
//! # E14. "The cross product between AB and c" (section 2.1.2)
//!
//! *Right:* the outer product `(a ^ b) ^ c`; there is no cross product of a bivector and a
//! vector. It equals `det[a b c] I`, the signed volume.
//!
//! *Test:* `errata.rs::e14_trivector_is_the_outer_product_with_c`.
//!
//! # E15. The rejection is introduced as "the projection" (section 2.3.4)
//!
//! *Report:* the second "The equations for the projection is given by:" introduces
//! `a_perp B = (a ^ B) B^-1`.
//!
//! *Right:* that is the rejection; the formula itself is right (`a_perp . B = 0` and
//! `a_par + a_perp = a`).
//!
//! *Test:* `errata.rs::e15_projection_and_rejection_split_a_vector`.
//!
//! # E16. Editorial: section numbers and titles
//!
//! The subsections of 2.4 are numbered 2.1.4 and 2.1.5 in the text (2.4.1 and 2.4.2 in the
//! table of contents), and 3.1 is titled "Defining a Plane from a Polygon" in the text but "from
//! a Triangle" in the contents (the method handles triangles only). No test: nothing to compute.
