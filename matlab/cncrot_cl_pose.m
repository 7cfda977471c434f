% CNCROT_CL_POSE  The pose of CL points (tool tip and direction).
%   P = cncrot_cl_pose(CL) for CL N-by-6 rows [x y z i j k] (the tool tip in mm and the tool
%   direction, any length but zero, in workpiece coordinates) gives 4-by-4-by-N poses:
%   P(1:3,4) the tip, P(1:3,3) the direction made a unit vector, P(1:3,1) the component of
%   the workpiece X axis perpendicular to it (of Y when |i| >= 0.9 after scaling to unit
%   length), P(1:3,2) = P(1:3,3) x P(1:3,1). The pose cncrot_machine_tcp_inverse takes for
%   CL rows and `cncrot path` for each point, bit for bit, on machines of fewer than three
%   rotary axes (which match the direction only).
%   P = cncrot_cl_pose(CL, P0) carries each row's X' from the row before (the first from
%   the 4-by-4 pose P0) by the smallest turn between their directions: no turn about the
%   tool between rows, where the X' above switches at |i| = 0.9 (a direction 120 degrees or
%   more from the one before takes the X' above). What a machine of three rotary axes
%   needs on CL rows: cncrot_machine_tcp_inverse and `cncrot path` carry the frame so
%   from where the machine stands.
%
%   Example:
%     P = cncrot_cl_pose([10 20 5 0 0 2]);   % eye(3) and the tip [10; 20; 5]
%     Q = cncrot_cl_pose([0 0 0 1 0 0], cncrot_cl_pose([0 0 0 1 0 1.732050807568877]));
%     Q(1:3,1)   % [0; 0; -1]: X' stays in the XZ plane (alone, [1 0 0]'s X' is [0; 1; 0])
%
%   See also CNCROT_MACHINE_TCP_INVERSE, CNCROT_MACHINE_TCP_FORWARD.
