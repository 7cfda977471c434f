% CNCROT_PROBE_PLANE  The least-squares plane through probed points, and its flatness.
%   [F, flatness, rms, turned] = cncrot_probe_plane(P)
%   [F, flatness, rms, turned] = cncrot_probe_plane(P, toward)
%   P: N-by-3 points (N >= 3), machine coordinates. F: 4-by-4 frame of the plane (origin at
%   the first point's foot on it, X' along the first two points, Z' on the tool's side: a
%   non-negative component along the machine's +Z, so that corners probed clockwise or
%   anticlockwise give the same plane, the right way up). toward: the side the tool comes
%   from as a direction [dx dy dz], or 'order' for the side of (P2-P1) x (P3-P1), as PLANE
%   POINTS (three points then give its rotation). turned: true when Z' was turned from the
%   side the points' order gave. flatness: the largest minus the smallest distance from the
%   plane; rms: the root mean square distance.
%   Errors: cncrot:tooFew, cncrot:coincident (also the first two points closer than 1e-3 of
%   the points' spread: X' would be the probe's noise), cncrot:collinear, cncrot:degenerate, ...
%
%   Example:
%     [F, flat, rms] = cncrot_probe_plane([0 0 5.01; 100 100 5.01; 0 100 4.99; 100 0 4.99])   % 0.02 0.01
%     [F, ~, ~, turned] = cncrot_probe_plane([0 0 0; 0 50 0; 100 50 -10; 100 0 -10])   % turned: true
%     F = cncrot_probe_plane([0 0 0; 0 50 0; 100 50 -10; 100 0 -10], 'order')           % Z' down
%
%   See also CNCROT_PROBE_EDGE, CNCROT_PROBE_FLANGE, CNCROT_FORM_VALUES.
