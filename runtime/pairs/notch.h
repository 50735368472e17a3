/* notch.h — pre-existing cracks (notches): neighbour pairs whose reference segment crosses a
 * notch quad are removed at set-up, so the two faces of the notch do not interact.
 *
 * A notch is a quad p1 p2 p3 p4 (3D corners, in order around it), split into the triangles
 * p1p2p3 and p1p3p4.  Touching rule: every point belongs to one side of a triangle's plane,
 * a point on the plane (within 1e-9 of the quad's size) to the "upper" side, the one the
 * normal points to, oriented so that its largest component is positive (for a notch in the
 * plane z = c: a particle at z = c counts as above it).  A segment crosses the quad when its
 * ends lie on different sides and the point where it meets the plane lies in the closed quad
 * (rim and diagonal included).  So pairs lying in the plane are never cut, and particles on
 * the plane stay with the upper side: cut off from the particles below, linked to those above.
 * See notch.c. */
#ifndef SPHRT_NOTCH_H
#define SPHRT_NOTCH_H

/* 1 when the closed segment p-q crosses the quad (rule above), else 0.  Symmetric in p, q:
 * the ends are ordered lexicographically before the test, so (p, q) and (q, p) give the
 * same answer bitwise. */
int sph_segment_crosses_quad(const double p[3], const double q[3], const double quad[4][3]);

/* Removes from the CSR neighbour lists (start[n+1], nb; both directions) every pair (i, j)
 * whose reference segment X_i-X_j crosses one of the nquads quads, compacting nb in place
 * (every list keeps its order) and updating start.  X holds n×dim coordinates: (x, y, z) in
 * 3D, (x, z) in 2D where the particles lie at y = y_plane (ignored in 3D).  The removal is
 * symmetric: (j, i) goes with (i, j).  Returns the new number of list entries, start[n].
 * quad_cuts (NULL, or nquads entries): 1 for each quad that is the first one some pair
 * crosses (the quads are tried in order), 0 for a quad that cuts nothing on its own. */
long sph_drop_notch_pairs(const double *X, int n, int dim, double y_plane, int *start, int *nb,
                          const double (*quads)[4][3], int nquads, int *quad_cuts);

#endif
