% CNCROT_PROBE_FLANGE  The paper's flange probing: the tilt of a flange from four points.
%   [angles, F] = cncrot_probe_flange(A1, A2, B1, B2)
%   A1, A2: two points probed along the machine's X; B1, B2: two along Y (machine
%   coordinates, 3 elements each). angles: 1-by-3, the tilt as extrinsic angles about X, Y,
%   Z for CYCLE600 (_INEXIN = 0, _BIN_IN = 57); F: the 4-by-4 frame of the tilted plane.
%   The plane through both directions is exact (not two independent slopes).
%   Errors: cncrot:coincident, cncrot:collinear, cncrot:notFinite, cncrot:badSize, ...
%
%   Example (a flange rising 10 mm over 100 mm along X):
%     a = cncrot_probe_flange([0 0 0], [100 0 10], [0 0 0], [0 100 0])   % 0 -5.7106 0
%
%   See also CYCLE600, CNCROT_PROBE_PLANE, CNCROT_PROBE_EDGE.
