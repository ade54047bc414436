// overlay.hpp -- the exact overlay: node a set of directed, weighted edges, give every
// face its winding numbers, keep the faces a rule selects, and return the regularized
// result -- as exact boundary edges (to feed another overlay) or as rings with holes
// whose vertices are the correctly rounded exact vertices.
//
// Geometry (class Geo, shared by the overlays of one operation):
//  * points: exact sums of two doubles (DD; a plain double has lo = 0, the vertex a + b
//    of a convex piece sum is TwoSum(a, b));
//  * lines: through two points -- every edge lies on one (its supporting line);
//  * vertices: a point, or the crossing of two lines (a rational point; never rounded).
// An edge runs along its line from one vertex to another, with an integer weight and a
// layer (0 or 1). Closed counter-clockwise rings of weight-1 edges have winding number 1
// inside; the winding numbers (w0, w1) of a face sum the rings of each layer, and the
// rule keeps a face or not: the union of layer 0 is w0 >= 1, a difference w0 >= 1 and
// w1 <= 0. Because vertices are kept as line crossings, the boundary edges of one
// overlay are exact input for the next (the cascaded union) without any growth in the
// degree of the predicates.
//
// One run (n edges, k intersecting pairs):
//  1. the input vertices sorted by (x, y) and equal ones merged (exact);
//  2. candidate pairs: boxes swept along x (boxes.hpp); each pair classified by the
//     sides of its four endpoints against the other's line: disjoint, touching (an
//     endpoint on the other edge), collinear overlap, or a proper crossing (a new vertex);
//  3. every edge's split points sorted along it, equal ones united (union-find): the
//     same point found by different pairs becomes one vertex, with no global hashing of
//     rational points;
//  4. the pieces between consecutive split points are the arrangement's edges; pieces
//     joining the same two vertices (collinear overlaps) are merged, weights added;
//  5. one plane sweep over the pieces (which no longer cross) gives each the winding
//     numbers below and above it: below the lowest piece starting at a vertex lies what
//     is above the piece just under that vertex;
//  6. pieces whose sides the rule classifies differently are the boundary, directed with
//     the inside on the left. For the final result, rings are traced (at a vertex with
//     several, the next edge is the first clockwise from the way back, so rings split at
//     pinch points), collinear vertices dropped (parallel lines), each ring's orientation
//     read at its lowest vertex, each hole given its exterior by a second sweep over the
//     boundary alone (the nearest boundary edge below a hole's first vertex belongs to
//     its exterior or to a sibling hole), and the vertices rounded to the nearest double
//     (ties to even), certified by an extended-precision filter or exact comparisons
//     with the neighbouring midpoints.
// Predicates, by degree in the input coordinates: orientation of points and the turn
// between two lines, 2; side of a crossing against a line, 4; order of two vertices
// along a line or in the sweep, 5 (3 for a point against a crossing). Each is evaluated
// in FE (filtered double) and, only when that cannot tell, in Dy (exact): exactnum.hpp.
//
// The parts, by stage: overlay_geo.hpp (coordinates, points, lines, vertices, the
// predicates on them, rules, edge and ring types), overlay_run.hpp (class Overlay, steps
// 1 to 4), overlay_trace.hpp (steps 5 and 6), overlay_lines.hpp (polyline clipping and
// lower-dimensional parts), overlay_round.hpp (the contract after rounding, the
// cascaded union, helpers). Include this file, not the parts.
#pragma once

#include "overlay_geo.hpp"
#include "overlay_lines.hpp"
#include "overlay_round.hpp"
#include "overlay_run.hpp"
#include "overlay_trace.hpp"
