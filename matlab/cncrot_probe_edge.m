% CNCROT_PROBE_EDGE  The turn about a tilted plane's normal that lays X' along a probed edge.
%   [angle, F2] = cncrot_probe_edge(F, E1, E2)
%   F: the active 4-by-4 plane; E1, E2: two points along the edge (machine coordinates).
%   angle: degrees about the plane's Z'; F2 = F * Rz(angle), the origin unchanged.
%   Errors: cncrot:coincident (E1 = E2), cncrot:collinear (edge along the normal), ...
%
%   Example:
%     a = cncrot_probe_edge(eye(4), [0 0 0], [100 100 0])   % 45
%
%   See also CNCROT_PROBE_PLANE, CNCROT_PROBE_FLANGE.
