/// @file distance.h
/// Exact minimum distance and proximal points between two solid right circular cylinders
/// (Agarwal, Srivatsan & Bandyopadhyay 2016, with a dual certificate that makes the answer exact).
#ifndef PROX_DISTANCE_H
#define PROX_DISTANCE_H

#include "shapes.h"

/// The cylinder feature a proximal point lies on.
typedef enum prox_feature {
    PROX_FEAT_NONE = 0,
    PROX_FEAT_LATERAL,  ///< the cylindrical surface S
    PROX_FEAT_BASE,     ///< interior of the base disk D^b
    PROX_FEAT_TOP,      ///< interior of the top disk D^t
    PROX_FEAT_RIM_BASE, ///< the base circle C^b
    PROX_FEAT_RIM_TOP,  ///< the top circle C^t
    PROX_FEAT_INSIDE    ///< the point is interior (overlap witness)
} prox_feature;

/// Which primitive pair produced the minimum.
typedef enum prox_pair_kind {
    PROX_PAIR_NONE = 0,  ///< no minimum computed (error) or overlap witness only
    PROX_PAIR_SS,        ///< surface-surface P(S,S); a disk against a side (perpendicular axes) is
                         ///< reported as CS, its minimum being attained at a rim point too
    PROX_PAIR_CS,        ///< circle (rim of one) - surface (of the other), P(C,L) - r
    PROX_PAIR_CD,        ///< circle - disk interior, P(D,C); parallel end faces (D-D) are reported
                         ///< here with point_set, as their minimum is also attained at a rim point
    PROX_PAIR_CC,        ///< circle - circle P(C,C)
    PROX_PAIR_OVERLAP    ///< the solids overlap; p1 = p2 is a common point
} prox_pair_kind;

/// Agarwal's case of the initial P(S1,S2) classification (Fig. 3): 1 both feet on the cylinders,
/// 21 / 22 one foot off (Case 2.1 / 2.2), 3 both off. 0 when parallel axes skip it.
typedef enum prox_agarwal_case {
    PROX_CASE_NONE = 0,
    PROX_CASE_1 = 10,
    PROX_CASE_2_1 = 21,
    PROX_CASE_2_2 = 22,
    PROX_CASE_3 = 30
} prox_agarwal_case;

/// Result of prox_rcc_distance. Start from {0}.
typedef struct prox_rcc_result {
    prox_status status;
    double distance;            ///< 0 when the solids overlap or one contains the other
    prox_vec3 p1;               ///< proximal point on A (a common point when overlapping)
    prox_vec3 p2;               ///< proximal point on B (equal to p1 when overlapping)
    prox_pair_kind pair;        ///< primitive pair that produced the minimum
    prox_feature feature1;      ///< feature of A holding p1
    prox_feature feature2;      ///< feature of B holding p2
    prox_agarwal_case agarwal;  ///< the case of Agarwal's first-level classification
    int hierarchy_exact;        ///< 1 when Agarwal's hierarchy alone gave the certified minimum
    int interfere;              ///< the solids share at least one point
    int a_in_b;                 ///< A lies inside B (closed sets; Agarwal Fig. 2)
    int b_in_a;                 ///< B lies inside A
    int point_set;              ///< proximal points form a set (parallel faces or axes); one pair given
    double certificate_gap;     ///< disjoint: a lower bound on the distance from a separating direction
} prox_rcc_result;

/// Minimum distance, proximal points, interference and containment of two solid cylinders.
PROX_API prox_rcc_result prox_rcc_distance(const prox_rcc *a, const prox_rcc *b);

/// Scale of a pair used for tolerances: max(|cA - cB|, hA, hB, rA, rB), c the centres.
PROX_API double prox_rcc_pair_scale(const prox_rcc *a, const prox_rcc *b);

/// Support function of a cylinder in direction d (not necessarily unit): max over x in the cylinder of d.x.
PROX_API double prox_rcc_support(const prox_rcc *c, prox_vec3 d);
/// A point of the cylinder attaining prox_rcc_support(c, d).
PROX_API prox_vec3 prox_rcc_support_point(const prox_rcc *c, prox_vec3 d);
/// Closest point of the solid cylinder to x (x itself when inside).
PROX_API prox_vec3 prox_rcc_closest_point(const prox_rcc *c, prox_vec3 x);
/// 1 when x lies in the closed solid cylinder enlarged by tol (tol >= 0, absolute).
PROX_API int prox_rcc_contains_point(const prox_rcc *c, prox_vec3 x, double tol);

#endif
