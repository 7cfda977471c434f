% CNCROT_PROBE_PLANE  The least-squares plane through probed points, and its flatness.
%   [F, flatness, rms] = cncrot_probe_plane(P)
%   P: N-by-3 points (N >= 3), machine coordinates. F: 4-by-4 frame of the plane (origin at
%   the first point's foot on it, X' along the first two points, Z' on the side of
%   (P2-P1) x (P3-P1); three points give PLANE POINTS's rotation). flatness: the largest minus
%   the smallest distance from the plane; rms: the root mean square distance.
%   Errors: cncrot:tooFew, cncrot:coincident, cncrot:collinear, cncrot:degenerate, ...
%
%   Example:
%     [F, flat, rms] = cncrot_probe_plane([0 0 5.01; 100 100 5.01; 0 100 4.99; 100 0 4.99])   % 0.02 0.01
%
%   See also CNCROT_PROBE_EDGE, CNCROT_PROBE_FLANGE, CNCROT_FORM_VALUES.
