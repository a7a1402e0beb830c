/* Internal: every tolerance of the library, named once, each with why it has its value.
 * Relative tolerances multiply the pair's scale S (max of the centre distance and the sizes, as in
 * tests/data/README.md) unless the line says otherwise; eps is DBL_EPSILON. */
#ifndef PROX_CORE_TOL_H
#define PROX_CORE_TOL_H

#include <float.h>

/* Certificate slack: a disjoint answer is proved when gap(n) >= |p2 - p1| - PROX_TOL_CERT S.
 * gap(n) and |p2 - p1| are each computed to a few ulps of S, so 64 eps covers both roundings. */
#define PROX_TOL_CERT (64.0 * DBL_EPSILON)

/* Two unit directions are parallel when |u x v| <= PROX_TOL_PARALLEL: the primitive solvers then
 * take their parallel branch (a set of closest points), and the point-set flags are raised. Below
 * it the feet of a common perpendicular move by more than 1e-4 S per ulp of the directions. */
#define PROX_TOL_PARALLEL 1e-12

/* Feet of the common perpendicular of two axes are well conditioned when |wA x wB| >= this (about
 * 1e-3 rad): an error e in the directions moves the feet by e/|wA x wB| <= 1e3 e, which keeps Case 1's
 * uncertified S-S answer at 1e-13 S. Below it the S-S normal comes from rejections and the answer
 * goes through the certificate. Squared form: PROX_TOL_WELL_COND2. */
#define PROX_TOL_WELL_COND 1e-3
#define PROX_TOL_WELL_COND2 1e-6

/* Two candidate distances within PROX_TOL_TIE S are a tie: the one with the more informative
 * feature pair is kept (the answer is the same to 1e-9 S, the flags differ). */
#define PROX_TOL_TIE 1e-9

/* A direction within |sin| <= PROX_TOL_FACE of a face normal or of perpendicular to a cylinder axis
 * supports the whole face or side segment: witness points are then taken from that set, not from
 * its one extreme point. MCNP decks print directions to about 10 digits, so flush faces in a deck
 * are parallel to ~1e-10. */
#define PROX_TOL_FACE 1e-9

/* A point's foot on a polytope face that passed the face's edge tests lies in the solid; one beyond
 * a plane by more than PROX_TOL_FOOT of the size is a collapsed face's false foot (a face of zero
 * width bounds only across its segment). Within it: the planes' own rounding, 5e-11 of the size
 * measured for a hexagonal prism placed 1e6 sizes from the origin. */
#define PROX_TOL_FOOT 1e-9

/* The depth's ridge of one cylinder is solved in the ridge plane (the other cylinder's shadow, an
 * ellipse of semi-axes r and r |cos|) only while b / a = |cos| of the axes' angle exceeds 1e-3: a
 * thinner ellipse (the other axis within 0.06 degrees of the ridge plane, ~0.1 % of random pairs)
 * curves at its tips at b^2 / a, where its feet are ill-conditioned; the rims' quartics take it. */
#define PROX_TOL_RIDGE_THIN 1e-3

/* The witnesses of an overlapping answer give its normal as (p1 - p2) / |p1 - p2| when that lies
 * within 1 - cos <= PROX_TOL_NORMAL_AGREE (~1.4e-6 rad) of the search's direction: a direction
 * polished to 1e-8 rad makes r x 1e-8 of p2 - p1 - sd n, the witness pair is exact to second order;
 * farther apart the two name different contacts (or p1 - p2 is rounding) and the direction is kept. */
#define PROX_TOL_NORMAL_AGREE 1e-12

/* A radial offset below 64 eps (|offset| + r) is rounding noise: its direction means nothing
 * (coaxial circles, a point on an axis). */
#define PROX_TOL_NOISE (64.0 * DBL_EPSILON)

/* Relative stopping tolerance of the support-function searches (separating axis, portal
 * refinement): the bound they certify is within 1e-13 S of the optimum, below the 1e-12 S the
 * answers promise. */
#define PROX_TOL_SEARCH 1e-13

/* The touching band: pairs within PROX_TOL_TOUCH S of touching may be reported either way (the
 * accuracy the answers promise). A touching pair's solids may share no point at all in floating point,
 * so a common point within this of both solids is accepted as the overlap witness. */
#define PROX_TOL_TOUCH 1e-12

/* Scene broad phase: bounding volumes are enlarged by this relative slack, so that a pair whose
 * exact distance equals the query's threshold is never culled by the rounding of a bound. */
#define PROX_TOL_BROAD 1e-13

/* Bounding boxes and spheres that scenes build from the generic body (core/body.h: TRC, REC, ELL,
 * RHP, WED, ARB) are enlarged by PROX_TOL_BOUND x (|c| + extent): the reference point c, the geometry
 * relative to it and the support function are each a few ulps off, and 64 eps covers their sum with
 * room to spare; a looser bound only costs a few more candidates. */
#define PROX_TOL_BOUND (64.0 * DBL_EPSILON)

/* ---- primitive and circle geometry (src/core/circle*.c, src/distance primitives, boxes) ---- */

/* A point within PROX_TOL_AXIS (8 eps) x the scale of an axis lies on it: every angle around the axis is
 * then equidistant (the set case of point-circle, point-surface, circle-circle contacts). */
#define PROX_TOL_AXIS (8.0 * DBL_EPSILON)

/* A radial offset below PROX_TOL_RADIAL x (axial coordinate, offset, radius) is rounding noise of the
 * rejection from the axis: any perpendicular direction is then as good as the computed one
 * (prox_cyl_signed: the outward normal of a point on the axis). */
#define PROX_TOL_RADIAL 1e-12

/* A segment parameter within PROX_TOL_PARAM of [0, 1] is an endpoint up to the rounding of the
 * parameter (a crossing at an endpoint): it is clamped onto the segment instead of dropped. */
#define PROX_TOL_PARAM 1e-12

/* Closest points of two segments: when sin^2 of their angle is below PROX_TOL_SEG_PARALLEL2 the 2x2
 * system is singular to rounding and s = 0 is taken; the endpoint pairs tried within 1e-3 rad of
 * parallel (PROX_TOL_WELL_COND2) then give the answer. */
#define PROX_TOL_SEG_PARALLEL2 1e-14

/* Box-box separating axes: edge cross products a_i x b_j shorter than this (the sine of the edges'
 * angle) are skipped; the face axes and the other cross axes decide. Skipping costs at most this x scale
 * in depth (the Minkowski facet of two edges at angle e differs from the facets of the plane
 * orthogonal to them by O(e size)), far inside the 1e-9 S depth accuracy. */
#define PROX_TOL_EDGE_AXIS 1e-10

/* An angle below PROX_TOL_FLAT (radians) changes a cosine by at most 5e-17 (second order): a circle
 * whose normal is that close to a line's direction projects along it onto a circle to 5e-17 r, and an
 * axis that close to a circle's plane is taken parallel to it. */
#define PROX_TOL_FLAT 1e-8

/* Circle-circle stationary points (Agarwal Sec. 3.5): after polishing, |h| = g'/2 below
 * PROX_TOL_CC_STAT x scale^2 is stationary; a spurious root of the squared degree-8 equation keeps
 * |h| = 2 |C.P'|, of the order of the scale. */
#define PROX_TOL_CC_STAT 1e-8

/* The half-angle polynomial of the circle-circle stationary points in one frame serves every angle
 * when its leading coefficient is at least PROX_TOL_CC_LEAD of its largest: by Cauchy's bound every
 * root then has |t| <= 1 + 1 / PROX_TOL_CC_LEAD (its angle at least ~2e-3 rad from pi, the angle t
 * sends to infinity), and a rounding of eps of the largest coefficient moves a root by at most
 * ~eps / PROX_TOL_CC_LEAD relative, which the Newton polish removes. Below it the frame a quarter
 * turn away is tried, and when neither frame qualifies both are solved. */
#define PROX_TOL_CC_LEAD 1e-3

/* Two circles are coaxial (the distance from one to the other is constant) when the normal of b is
 * along a's and b's centre on a's axis to 16 eps (relative): the degree-8 equation vanishes there. */
#define PROX_TOL_COAXIAL (16.0 * DBL_EPSILON)

/* Circle a meets b's axis when the crossing point is within PROX_TOL_CC_AXIS_MEET x r_a of the circle:
 * the distance has a cusp there that Newton cannot polish, so the angle is offered as it is (a wrong
 * extra angle is only one more candidate, never a wrong answer). */
#define PROX_TOL_CC_AXIS_MEET 1e-6

/* Stationary angles closer than this (radians) are one point: circle-circle (polished to ~1e-12 on
 * the trigonometric form), circle-line (the quartic's roots are polished further). */
#define PROX_TOL_CC_DEDUP 1e-9
#define PROX_TOL_CL_DEDUP 1e-10

/* Circle-line quartic in tan(theta/2): theta = pi is sent to infinity, so it is added when h(pi), the
 * leading coefficient, is below PROX_TOL_CL_PI x the largest coefficient (an extra angle is harmless). */
#define PROX_TOL_CL_PI 1e-6

/* Newton on an angle: a step below PROX_TOL_NEWTON_QUAD rad is in the quadratic regime (the error left
 * is of order step^2, below 1e-17); below PROX_TOL_DESCENT_ROUND rad a descent step's decrease of the
 * distance is rounding, so convergence is judged by |h| instead. */
#define PROX_TOL_NEWTON_QUAD 1e-9
#define PROX_TOL_DESCENT_ROUND 1e-7

/* ---- the fast RCC-RCC method (src/distance/rcc_rcc.c) ---- */

/* Axes with |wA x wB| <= PROX_TOL_NO_FEET have no usable common perpendicular: its feet, divided by
 * |wA x wB|^2, would move by more than 0.1 S per ulp of the directions, so Agarwal's first-level
 * classification and the S-S candidate are skipped and the other candidates decide. */
#define PROX_TOL_NO_FEET 1e-15

/* Prediction of the feature supporting a direction n (a guess, every candidate it selects is
 * certified): the end disk when n is within PROX_PREDICT_ANGLE rad (~0.57 degree) of the axis, the
 * lateral surface when within that angle of perpendicular to it, else a rim. */
#define PROX_PREDICT_ANGLE 1e-2

/* ---- support-function search (src/sat/sup_engine.c, rcc_depth.c) ---- */

/* A unit direction D is near a kink of phi when |D.w| < PROX_TOL_KINK (a ridge: a lateral line or a
 * box face supports) or 1 - |D.W| < PROX_TOL_CONE (a cone point: a disk supports; |P D| < 1e-5 there).
 * The nonsmooth search stalls a few 1e-7 rad off a kink; within these it is snapped onto the kink,
 * escaped from along the centre subgradient, or polished on it. */
#define PROX_TOL_KINK 1e-5
#define PROX_TOL_CONE 5e-11

/* Near a cone point (|P D| below PROX_TOL_CONE_PERP) the radial part of a cylinder's support point is
 * arbitrary: the centre of the subdifferential drops it. */
#define PROX_TOL_CONE_PERP 1e-6

/* Three values of phi PROX_TOL_KINK_PROBE rad apart decide whether a kink on a ridge is a minimum
 * (Newton cannot converge onto a kink); wider than the search's stall, narrower than any feature. */
#define PROX_TOL_KINK_PROBE 1e-7

/* Two search starts closer than 1 - cos = PROX_TOL_SAME_START are one. */
#define PROX_TOL_SAME_START 1e-8

/* Newton on the sphere has converged when its decrement is below PROX_TOL_DECREMENT x S (phi's own
 * rounding is ~1e-16 S), or its step below PROX_TOL_STEP rad (the direction's rounding). */
#define PROX_TOL_DECREMENT 1e-17
#define PROX_TOL_STEP 1e-13

/* Rounding of phi (its terms are ~S each): values within PROX_TOL_PHI_ROUND x S are equal (a kink's
 * three-point test, the snap onto a kink accepts a value that much worse). Below it a Newton
 * decrement no longer judges a step, which the general engine then judges by the gradient across the
 * direction (sat/convex.c): stopping there leaves the direction ~sqrt(this / curvature) off, support
 * points ~1e-8 S off the closest pair (the old engine, sat/sup_engine.c, stops at PROX_TOL_DECREMENT). */
#define PROX_TOL_PHI_ROUND (16.0 * DBL_EPSILON)

/* The snap onto a kink accepts a value of phi at most PROX_TOL_SNAP x S worse (its rounding): any
 * more and the distance it reports falls short of the true one (face-lat pairs 3e-12 short when the
 * snap accepted 1e-12 S). GJK on the support points of K stops when its two bounds meet to the same. */
#define PROX_TOL_SNAP (4.0 * DBL_EPSILON)

/* The depth certificate of the any-pair support method (src/sat/convex.c): the cover of the sphere
 * of directions stops when every cell's lower bound is within PROX_TOL_DEPTH_CERT x S of the depth
 * found, ten times inside the 1e-9 S the depths promise. */
#define PROX_TOL_DEPTH_CERT 1e-10

/* The accuracy bar of penetration depths (1e-9 S): an overlapping signed distance whose proved
 * enclosure (prox_signed_result.sd_lower, sd_upper) is this narrow is reported certified. */
#define PROX_TOL_DEPTH_BAR 1e-9

/* A Newton bracket on an angle narrower than PROX_TOL_ANGLE rad is at the rounding of the angle. */
#define PROX_TOL_ANGLE 1e-14

/* Rim-rim contact normal: the line between the points when they are more than PROX_TOL_CC_NEAR S
 * apart (its direction error eps S / d is then below 1e-12, and the certificate loses only its square);
 * nearer, the cross product of the two tangents, which stays accurate as the points meet. */
#define PROX_TOL_CC_NEAR 1e-4

/* The tangents' cross product is used as that normal only when it exceeds PROX_TOL_TANGENT x |tangent|
 * (tangents not parallel to ~1e-6 rad): nearer to parallel its direction is rounding noise. */
#define PROX_TOL_TANGENT 1e-6

/* Circle-circle degree-8 polynomial, built in the frame of circle a normalised by its radius: its
 * coefficients grow as M^4, M = (|cb - ca| + ra + rb) / ra, so it is formed only for M <= PROX_CC_RANGE
 * (M^4 <= 1e256, far from overflow). Beyond it circle a is a point to within 1e-64 of the pair's extent,
 * and the pair is solved from circle b, or (both beyond) any rim point stands for each rim. */
#define PROX_CC_RANGE 1e64

/* ---- convex polytopes (src/core/polytope*.c, src/distance/poly_pairs.c) ---- */

/* A polytope macrobody is degenerate when a feature it needs vanishes below PROX_TOL_POLY_DEGEN
 * relative: WED sides with |sin(v1, v2)| at or below it, an RHP hexagon side shorter than it times the
 * hexagon's size, ARB corners closer than it times the body's size or a face with no corner that
 * far behind its plane. Flat bodies above it (a WED at 1e-6 rad) are valid and solved exactly. */
#define PROX_TOL_POLY_DEGEN 1e-9

/* An ARB face is planar when every corner lies within PROX_TOL_ARB_PLANAR x size of the face's
 * plane (Newell normal through the corners' mean), and a corner counts as behind a face plane to the
 * same slack. Cards print corners to ~10 digits, so a face written as planar is planar to ~1e-10; a
 * larger offset is a fault of the card, not rounding. */
#define PROX_TOL_ARB_PLANAR 1e-9

/* ---- curved macrobodies (src/core/ellipse2.c, cone.c, ecyl.c, ellb.c) ---- */

/* Point-ellipse secular equation (core/ellipse2.c): the safeguarded Newton iteration stops when its
 * step is below PROX_ELLIPSE_STEP relative (Newton is then quadratic: the error left is ~ step^2),
 * or after PROX_ELLIPSE_MAXIT steps (bisection alone needs at most ~2100 for any double bracket;
 * with the Newton steps it takes about 4 on average over random ellipses and points). */
#define PROX_ELLIPSE_STEP (4.0 * DBL_EPSILON)
#define PROX_ELLIPSE_MAXIT 2200

/* A point within PROX_ELLIPSE_AXIS_Z x the minor semi-axis of the major axis is on it: the secular
 * equation's derivative carries 1 / Z (Z ~ that offset x e1 / e0^2) and overflows for a subnormal
 * offset (the nearest point then came out at the corner (e0, e1)), while the on-axis closed form is
 * exact to within the offset, far below any rounding of the answer. */
#define PROX_ELLIPSE_AXIS_Z 1e-150

/* ---- cell check (src/cells/classify.c, check.c) ---- */

/* Rounding allowance of the box-surface classification, relative to the sum of the magnitudes of
 * every term of the centred quadric form: each bound is a sum of at most ~20 rounded products, so
 * its error is below ~20 eps of that sum; 64 eps leaves a factor 3 to spare. */
#define PROX_TOL_CLASSIFY (64.0 * DBL_EPSILON)

/* Two surfaces whose normalised global coefficients agree to PROX_TOL_SURF_SAME are one surface for
 * the cell check (a PZ card and a macrobody facet on the same plane, a filled window's boundary
 * mapped into the universe's frame): they differ by rounding, a sliver 1e-12 of the model thin, far
 * below any resolution, which as two surfaces would keep every box along them undecided. */
#define PROX_TOL_SURF_SAME 1e-12

/* Bounding boxes of cells are widened by PROX_TOL_CELL_BOX relative: they only prune (a cell whose
 * box misses a box cannot claim it), so widening costs nothing and covers the rounding of the
 * inverse of a well-conditioned quadric matrix (condition checked against PROX_TOL_CELL_PD). */
#define PROX_TOL_CELL_BOX 1e-6
#define PROX_TOL_CELL_PD 1e-8

/* Support features of a polytope for the depth witnesses: corners within PROX_TOL_POLY_FEATURE S of
 * the support value along the depth axis form the feature (a face nearly facing the axis counts as
 * the face). The witnesses' offset along the axis is then within this of the depth, below the 1e-9 S
 * the depths promise, and the projections of the two features still meet when rounding tilts a face. */
#define PROX_TOL_POLY_FEATURE 1e-10

/* ---- containment of any pair (src/query/contain_any.c) ---- */

/* The branch-and-bound of a curved body's clearance in a curved body (over the normals of B's lateral
 * surface or of an ellipsoid B) closes a cell when its second-order bound is within
 * PROX_TOL_CONTAIN_BB S of the best value found: the clearance is certified to that, the accuracy the
 * answers promise; the bound is quadratic at a smooth maximum and linear at a kink, so the cells left
 * open stay few. Only pairs within this of touching from inside can be misjudged as nested. */
#define PROX_TOL_CONTAIN_BB 1e-12

/* The exact witnesses of a disjoint pair more than PROX_TOL_WITNESS_DIR S apart define the normal to
 * 1e-12 rad (each point is good to ~1e-16 S): the generic signed distance takes their direction in
 * place of the support method's maximiser of the flat -phi (src/query/query.c). */
#define PROX_TOL_WITNESS_DIR 1e-4

/* Coaxial solids of revolution (src/distance/curved_pairs.c): axes parallel within this angle and
 * each body's axis point within this x the pair's scale (plus 8 ulps of its coordinates, the input's
 * own precision) of the common axis. Moving the second body onto the first axis then moves it by at
 * most ~1e-13 S, and the distance and signed distance, being 1-Lipschitz under such moves, by no
 * more: well inside the 1e-12 S the answers promise. */
#define PROX_TOL_COAXIAL_REV 1e-13

/* Lattice translations (src/cells/window_bound.c): the two planes of a pair of a lattice element are
 * opposite when their unit normals sum to within PROX_TOL_LAT_PLANES, and a hexagonal element's third
 * pair agrees with the first two (element (-1,1,0) beyond its fifth surface) within PROX_TOL_LAT_PLANES
 * x the element's width. Lattice cards give their planes to a few digits, the same plane pairs
 * in both senses: a looser agreement is not a lattice prox can translate, and its windows stay as they
 * were (not bounded: undecided). */
#define PROX_TOL_LAT_PLANES 1e-9

/* Polytope depth axes (src/distance/poly_pairs.c): an edge pair's Gauss-map arc test (triple products
 * of unit face normals, rounded by a few ulps) decides only when every sign clears PROX_TOL_GAUSS_ARC;
 * a pair too close to tell keeps its axis, evaluated by the full supports, so no Minkowski facet is
 * lost to rounding. */
#define PROX_TOL_GAUSS_ARC 1e-9

/* An edge pair whose arcs clearly cross takes its separation from the two edges' corners (O(1)) when
 * the edges' sine is at least PROX_TOL_GAUSS_AXIS: the unit cross product then carries at most
 * ~eps / 1e-3 = 2e-13 rad of rounding, far inside the arc margin, so it stays inside both normal cones
 * and the corners are the supports. Nearer-parallel pairs are evaluated by the full supports. */
#define PROX_TOL_GAUSS_AXIS 1e-3

#endif
