function test_cncrot(cases_file)
% TEST_CNCROT  The MATLAB/Octave suite: the paper's numbers, every error path, and parity
% with the C library (cases_file, written by c_tests/parity.c) bit for bit.
  passed = 0; failed = 0;
  function check(ok, what)
    if ok
      passed = passed + 1;
    else
      failed = failed + 1;
      fprintf(2, 'FAILED: %s\n', what);
    end
  end
  function expect_error(id, f, what)
    try
      f();
      check(false, [what ': no error']);
    catch err
      check(strcmp(err.identifier, id), sprintf('%s: got %s, expected %s', what, err.identifier, id));
    end
  end
  % A function's result, or the identifier of its error.
  function r = outcome(f)
    try
      r = f();
    catch err
      r = err.identifier;
    end
  end
  % The identifier, and a message that begins with the function's name, holds no C status
  % name, and contains each of `parts` (the argument, what it must be, what was given).
  function expect_message(id, f, what, fname, varargin)
    try
      f();
      check(false, [what ': no error']);
    catch err
      ok = strcmp(err.identifier, id) && strncmp(err.message, [fname ': '], numel(fname) + 2) ...
           && isempty(strfind(err.message, 'CNCROT_STATUS'));
      for k = 1:numel(varargin)
        ok = ok && ~isempty(strfind(err.message, varargin{k}));
      end
      check(ok, sprintf('%s: got %s "%s", expected %s with %s', what, err.identifier, err.message, id, strjoin(varargin, ' | ')));
    end
  end

  % The paper's numbers (conventions.md).
  R = cncrot_matrix(0, 57, [30 45 60]);
  check(max(max(abs(R - [0.3536 -0.5732 0.7392; 0.6124 0.7392 0.2803; -0.7071 0.3536 0.6124]))) < 1e-4, 'Example 2 matrix');
  check(max(abs(cncrot_angles(1, 39, R) - [37.7923 20.7048 49.1066])) < 1e-4, 'intrinsic 39');
  check(max(abs(cncrot_convert(0, 57, [30 45 60], 1, 57) - [-24.5972 47.6632 58.3345])) < 1e-4, 'intrinsic 57');
  check(max(abs(cncrot_convert(0, 57, [30 45 60], 0, 39) - [39.6392 -16.2799 50.3607])) < 1e-4, 'extrinsic 39');
  gud = cycle600(0, 'UFK600', 1, 57, 0,0,0, 30,45,60, 0,0,0, 1, 39, 0,0,0);
  check(strcmp(gud.CYC600_1, 'UFK600') && gud.CYC600_5 == 1 && gud.CYC600_6 == 39, 'Example 3 fields');
  check(max(abs([gud.CYC600_2 gud.CYC600_3 gud.CYC600_4] - [37.7923 20.7048 49.1066])) < 1e-4, 'Example 3 first call');
  gud = cycle600(0, 'UFK600', 1, 57, 0,0,0, 30,45,60, 0,0,0, 0, 39, 0,0,0);
  check(gud.CYC600_5 == 0 && max(abs([gud.CYC600_2 gud.CYC600_3 gud.CYC600_4] - [39.6392 -16.2799 50.3607])) < 1e-4, 'Example 3 second call');
  % Batches and additive calls.
  Rs = cncrot_matrix(1, 55, [10 20 30; 40 50 60]);
  check(isequal(size(Rs), [3 3 2]) && isequal(Rs(:,:,2), cncrot_matrix(1, 55, [40 50 60])), 'batch');
  [a, st] = cncrot_angles(1, 27, cncrot_matrix(1, 27, [40 90 10]));
  check(st == 1 && max(abs(a - [30 90 0])) < 1e-12, 'singular status');
  g1 = cycle600(1, 'H', 1, 1, 0,0,0, 30,0,0, 0,0,0, 1, 57, 0,0,0);
  g2 = cycle600(1, 'H', 1, 2, 0,0,0, 45,0,0, 0,0,0, 1, 57, 1,0,0, g1);
  g3 = cycle600(1, 'H', 1, 3, 0,0,0, 60,0,0, 0,0,0, 1, 57, 1,0,0, g2);
  check(max(abs([g3.CYC600_2 g3.CYC600_3 g3.CYC600_4] - [30 45 60])) < 1e-12, 'additive calls');

  % Error paths, with identifiers.
  expect_error('cncrot:badFlag', @() cncrot_matrix(2, 57, [1 2 3]), 'flag');
  expect_error('cncrot:badSequence', @() cncrot_matrix(1, 64, [1 2 3]), 'sequence 64');
  expect_error('cncrot:badSequence', @() cncrot_matrix(1, 22, [1 2 3]), 'repeated axis');
  expect_error('cncrot:notFinite', @() cncrot_matrix(1, 57, [1 NaN 3]), 'NaN');
  expect_error('cncrot:notFinite', @() cncrot_convert(1, 57, [Inf 0 0], 0, 39), 'Inf');
  expect_error('cncrot:incompleteSequence', @() cncrot_angles(1, 3, eye(3)), 'incomplete');
  expect_error('cncrot:notARotation', @() cncrot_angles(1, 57, 2 * eye(3)), 'not a rotation');
  expect_error('cncrot:notARotation', @() cncrot_angles(1, 57, diag([1 1 -1])), 'reflection');
  expect_error('cncrot:badSize', @() cncrot_matrix(1, 57, [1 2]), 'angles size');
  expect_error('cncrot:badSize', @() cncrot_angles(1, 57, eye(4)), 'matrix size');
  expect_error('cncrot:badClass', @() cncrot_matrix(1, 57, single([1 2 3])), 'class');
  expect_error('cncrot:badClass', @() cncrot_matrix(1, 57, 'abc'), 'char');
  expect_error('cncrot:complex', @() cncrot_matrix(1, 57, [1i 2 3]), 'complex');
  expect_error('cncrot:badArgument', @() cncrot_matrix(0.5, 57, [1 2 3]), 'non-integer flag');
  expect_error('cncrot:nargin', @() cncrot_matrix(1, 57), 'nargin');
  try
    [p, q] = cncrot_matrix(1, 57, [1 2 3]); %#ok<ASGLU>
    check(false, 'nargout: no error');
  catch err
    check(strcmp(err.identifier, 'cncrot:nargout'), ['nargout: got ' err.identifier]);
  end
  % _SW_REC = 0 recalculates as 1 does (positioning is cncrot_machine_choose's).
  g0 = cycle600(0, 'H', 0, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 0,0,0);
  g1 = cycle600(0, 'H', 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 0,0,0);
  check(isequal(g0.CYC600_2, g1.CYC600_2) && isequal(g0.CYC600_4, g1.CYC600_4), 'SW_REC 0');
  expect_error('cncrot:nameTooLong', @() cycle600(0, repmat('A', 1, 40), 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 0,0,0), 'long name');
  expect_error('cncrot:badClass', @() cycle600(0, 5, 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 0,0,0), 'name class');
  expect_error('cncrot:badFlag', @() cycle600(0, 'H', 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 0,2,0), 'ROT_INV 2');
  expect_error('cncrot:outOfRange', @() cycle600(0, 'H', 1, 57, 1e308,0,0, 0,0,0, 1e308,0,0, 1, 39, 0,0,0), 'overflowing frame');
  expect_error('cncrot:badClass', @() cycle600(0, 'H', 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 1,0,0, 7), 'previous gud');
  bad = gud; bad.frame(1,1) = 5;
  expect_error('cncrot:badState', @() cycle600(0, 'H', 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 1,0,0, bad), 'corrupt gud');
  bad = gud; bad.CYC600_2 = bad.CYC600_2 + 1e-12;
  expect_error('cncrot:badState', @() cycle600(0, 'H', 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 1,0,0, bad), 'edited angle');
  bad = gud; bad.CHECKSUM = bad.CHECKSUM + 1;
  expect_error('cncrot:badState', @() cycle600(0, 'H', 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 1,0,0, bad), 'edited checksum');
  bad = rmfield(gud, 'CHECKSUM');
  expect_error('cncrot:badState', @() cycle600(0, 'H', 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 1,0,0, bad), 'no checksum');
  bad = gud; bad.CYC600_1 = 42;
  expect_error('cncrot:badClass', @() cycle600(0, 'H', 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 1,0,0, bad), 'numeric CYC600_1');

  % Every class of double array Octave makes, in every MEX function: ranges, diagonal and
  % permutation matrices (compact objects in Octave), sparse, empty, 3-D.
  P = eye(3)([2 3 1], :);
  check(isequal(cncrot_matrix(1, 57, 0:30:60), cncrot_matrix(1, 57, [0 30 60])), 'range angles');
  check(isequal(cncrot_matrix(1:1, 57:57, [1 2 3]), cncrot_matrix(1, 57, [1 2 3])), 'range scalars');
  check(isequal(cncrot_convert(0, 57, 1:3, 1, 39), cncrot_convert(0, 57, [1 2 3], 1, 39)), 'range convert');
  check(isequal(cncrot_angles(1, 57, eye(3)), [0 0 0]), 'diagonal R');
  check(isequal(cncrot_matrix(1, 57, eye(3)), cncrot_matrix(1, 57, full(eye(3)))), 'diagonal angles');
  check(isequal(cncrot_convert(0, 57, P, 1, 39), cncrot_convert(0, 57, full(P), 1, 39)), 'permutation angles');
  check(isequal(cncrot_convert(0, 57, diag([10 20 30]), 1, 39), cncrot_convert(0, 57, full(diag([10 20 30])), 1, 39)), 'diagonal convert');
  check(isequal(cncrot_angles(1, 57, eye(3) * 1), [0 0 0]), 'diagonal times 1');
  check(isequal(cncrot_angles(1, 57, P), cncrot_angles(1, 57, full(P))), 'permutation R');
  [~, ~, Plu] = lu(magic(3));
  check(isequal(cncrot_angles(1, 27, Plu' * Plu), [0 0 0]), 'lu permutation product');
  expect_error('cncrot:notARotation', @() cncrot_angles(1, 57, Plu * diag([1 1 -1]) * Plu'), 'permutation reflection');
  expect_error('cncrot:badClass', @() cncrot_angles(1, 57, sparse(eye(3))), 'sparse R');
  expect_error('cncrot:badClass', @() cncrot_matrix(1, 57, sparse([1 2 3])), 'sparse angles');
  expect_error('cncrot:badClass', @() cncrot_convert(0, 57, sparse([1 2 3]), 1, 39), 'sparse convert');
  expect_error('cncrot:badClass', @() cncrot_matrix(sparse(1), 57, [1 2 3]), 'sparse flag');
  check(isequal(cncrot_matrix(int32(1), 57, [1 2 3]), cncrot_matrix(1, 57, [1 2 3])), 'int32 flag');
  check(isequal(cncrot_matrix(true, 57, [1 2 3]), cncrot_matrix(1, 57, [1 2 3])), 'logical flag');
  expect_error('cncrot:badClass', @() cncrot_matrix(1, 57, int8([1 2 3])), 'int8 angles');
  check(isequal(size(cncrot_matrix(1, 57, zeros(0, 3))), [3 3 0]), 'empty angles');
  check(isequal(size(cncrot_matrix(1, 57, [])), [3 3 0]), '[] angles');
  check(isequal(size(cncrot_convert(0, 57, zeros(0, 3), 1, 39)), [0 3]), 'empty convert');
  [ea, es] = cncrot_angles(1, 57, zeros(3, 3, 0));
  check(isequal(size(ea), [0 3]) && isequal(size(es), [0 1]), 'empty R');
  check(isequal(size(cncrot_angles(1, 57, [])), [0 3]), '[] R');
  expect_error('cncrot:badFlag', @() cncrot_matrix(2, 57, zeros(0, 3)), 'empty input still checks the flag');
  expect_error('cncrot:badSequence', @() cncrot_angles(1, 64, zeros(3, 3, 0)), 'empty input still checks the code');
  expect_error('cncrot:badSize', @() cncrot_matrix(1, 57, zeros(3, 0)), '3-by-0 angles');
  expect_error('cncrot:badSize', @() cncrot_matrix(1, 57, ones(1, 3, 2)), '3-D angles');
  expect_error('cncrot:badSize', @() cncrot_convert(0, 57, ones(2, 3, 2), 1, 39), '3-D convert');
  R3 = cat(3, eye(3), P);
  check(isequal(size(cncrot_angles(1, 57, R3)), [2 3]), '3-D R');
  expect_error('cncrot:badSize', @() cncrot_angles(1, 57, ones(3, 3, 2, 2)), '4-D R');
  g = cycle600(0:0, 'UFK600', 1:1, 57, 0,0,0, 0:0,45,60, 0,0,0, 1, 39, 0,0,0);
  check(isequal(g.CYC600_1, 'UFK600'), 'cycle600 with range scalars');
  g2 = g; g2.frame = eye(4);
  expect_error('cncrot:badState', @() cycle600(0, 'H', 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 1,0,0, g2), 'gud frame eye(4)');
  expect_error('cncrot:badClass', @() cycle600(0, 'H', 1, 57, sparse(0),0,0, 1,2,3, 0,0,0, 1, 39, 0,0,0), 'sparse position');

  % Input edges: names, integers beyond int32, rows named only where they mean something.
  expect_error('cncrot:badArgument', @() cycle600(0, ['AB' char(0) 'CD'], 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 0,0,0), 'NUL in name');
  expect_error('cncrot:badSize', @() cycle600(0, ['AB'; 'CD'], 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 0,0,0), 'char matrix name');
  expect_error('cncrot:badArgument', @() cycle600(0, 'MY HEAD', 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 0,0,0), 'space in name');
  expect_error('cncrot:nameTooLong', @() cycle600(0, repmat('A', 1, 32), 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 0,0,0), '32 characters');
  g = cycle600(0, repmat('A', 1, 31), 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 0,0,0);
  check(numel(g.CYC600_1) == 31, '31 characters');
  g = cycle600(0, '', 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 0,0,0);
  check(isempty(g.CYC600_1), 'empty name');
  expect_error('cncrot:badFlag', @() cncrot_matrix(2^31, 57, [1 2 3]), 'flag 2^31');
  expect_error('cncrot:badSequence', @() cncrot_matrix(1, -2^40, [1 2 3]), 'code -2^40');
  expect_error('cncrot:badArgument', @() cncrot_matrix(NaN, 57, [1 2 3]), 'NaN flag');
  messages = {};
  function remember(f)
    try
      f();
    catch err
      messages{end + 1} = err.message;
    end
  end
  remember(@() cncrot_matrix(2, 57, [1 2 3; 4 5 6]));
  remember(@() cycle600(0, 'H', 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 0,2,0));
  remember(@() cncrot_matrix(1, 57, [1 2 3; 4 NaN 6]));
  remember(@() cncrot_matrix(1, 57, [1 NaN 3]));
  check(numel(messages) == 4, 'four errors');
  check(isempty(strfind(messages{1}, 'row')), ['flag error names no row: ' messages{1}]);
  check(isempty(strfind(messages{2}, 'row')), ['cycle600 error names no row: ' messages{2}]);
  check(~isempty(strfind(messages{3}, 'row 2:')), ['batch error names its row: ' messages{3}]);
  check(isempty(strfind(messages{4}, 'row')), ['single-row error names no row: ' messages{4}]);

  % Names: conventions, dialects, rules and forms as MATLAB users write them, equal bit for
  % bit to the numeric calls (codes: a1 + 4*a2 + 16*a3, X = 1, Y = 2, Z = 3, none = 0).
  A = [30 45 60; 10 -20 170; 0 90 0];
  check(isequal(cncrot_convert('extrinsic', 'XYZ', [30 45 60], 'intrinsic', 'ZXY'), cncrot_convert(0, 57, [30 45 60], 1, 39)), 'pinned: convert by names');
  check(isequal(cncrot_matrix('intrinsic', 'ZYX', A), cncrot_matrix(1, 27, A)), 'pinned: matrix by names');
  check(isequal(cncrot_convert("extrinsic", "XYZ", A, "intrinsic", "ZXY"), cncrot_convert(0, 57, A, 1, 39)), 'double-quoted names');
  check(isequal(cncrot_convert('EXTRINSIC', 'xyz', A, 'Intrinsic', 'zXy'), cncrot_convert(0, 57, A, 1, 39)), 'names in any case');
  check(isequal(cncrot_convert(0, "ZX'Y''", A, 1, 'Z''X''Y'''''), cncrot_convert(0, 39, A, 1, 39)), 'primes ignored');
  check(isequal(cncrot_convert(0, "Z′X″Y", A, 1, 'ZXY'), cncrot_convert(0, 39, A, 1, 39)), 'Unicode primes ignored');
  check(isequal(cncrot_matrix('extrinsic', 'X0Z', A), cncrot_matrix(0, 49, A)), 'X0Z skips the second rotation');
  check(isequal(cncrot_matrix(1, '000', [1 2 3]), eye(3)), '000: no rotation');
  check(isequal(cncrot_convert(int8(0), uint8(57), A, true, int32(39)), cncrot_convert(0, 57, A, 1, 39)), 'integer classes');
  check(isequal(cncrot_convert(false, int64(57), A, uint16(1), single(39)), cncrot_convert(0, 57, A, 1, 39)), 'logical, int64, single');
  check(isequal(cncrot_angles('intrinsic', 'ZXY', cncrot_matrix(0, 'XYZ', [30 45 60])), cncrot_angles(1, 39, cncrot_matrix(0, 57, [30 45 60]))), 'angles by names');
  [a1, s1] = cncrot_angles(uint8(1), int16(27), cncrot_matrix(1, 27, [40 90 10]));
  [a2, s2] = cncrot_angles(1, 27, cncrot_matrix(1, 27, [40 90 10]));
  check(isequal(a1, a2) && isequal(s1, s2), 'angles with integer classes');
  g1 = cycle600('extrinsic', 'UFK600', 1, 'XYZ', 0,0,0, 30,45,60, 0,0,0, 'intrinsic', 'ZXY', 0,0,0);
  g2 = cycle600(0, 'UFK600', 1, 57, 0,0,0, 30,45,60, 0,0,0, 1, 39, 0,0,0);
  check(isequal(g1, g2), 'cycle600 by names');
  g1 = cycle600(int32(0), "UFK600", true, int8(57), 0,0,0, 30,45,60, 0,0,0, uint8(1), int32(39), false, int8(0), uint16(0));
  check(isequal(g1, g2), 'cycle600 with integer classes and a double-quoted name');
  d = cncrot_dialects();
  names = {'sinumerik', 'heidenhain', 'fanuc', 'syntec', 'twincat', 'haas'};
  codes = [d.SINUMERIK d.HEIDENHAIN d.FANUC d.SYNTEC d.TWINCAT d.HAAS];
  lines = {'ROT Z30', 'PLANE SPATIAL SPA+0 SPB+0 SPC+30 TURN FMAX', 'G68.2 X0 Y0 Z0 I0 J0 K30', 'G68.2 X0 Y0 Z0 I0 J0 K30', 'ROT Z30', 'G268 Q123 X0 Y0 Z0 I0 J0 K30'};
  for k = 1:numel(names)
    F = cncrot_program_lines(codes(k), lines{k});
    check(isequal(cncrot_program_lines(names{k}, lines{k}), F) && isequal(cncrot_program_lines(upper(names{k}), lines{k}), F) ...
          && isequal(cncrot_program_lines(int32(codes(k)), lines{k}), F) && ~isequal(F, eye(4)), ['dialect by name: ' names{k}]);
  end
  F = cncrot_program_lines(d.FANUC, 'G68.2 X1 Y2 Z3 I10 J20 K30');
  check(isequal(cncrot_program_write("fanuc", 'G68.2', F, int8(4)), cncrot_program_write(d.FANUC, 'G68.2', F, 4)), 'program_write by name');
  R4 = [F(1:3, 1:3) [0; 0; 0]; 0 0 0 1];
  check(isequal(cncrot_program_write('Heidenhain', "PLANE SPATIAL", R4), cncrot_program_write(d.HEIDENHAIN, 'PLANE SPATIAL', R4)), 'a double-quoted form');
  % Probing: the tool's side by default (clockwise corners turned up, and said so), the
  % points' order with 'order', a stated side, the same bits as the C library's default.
  cw = [0 0 0; 0 50 0; 100 50 -10; 100 0 -10];
  [Fu, ~, ~, tu] = cncrot_probe_plane(cw);
  check(tu && abs(Fu(3, 3) - 1 / sqrt(1.01)) < 1e-15 && abs(Fu(1, 3) - 0.1 / sqrt(1.01)) < 1e-15, 'probe: the tool''s side');
  [Fo, ~, ~, to] = cncrot_probe_plane(cw, 'order');
  check(~to && isequal(Fo(1:3, 3), -Fu(1:3, 3)) && isequal(Fo(1:3, 1), Fu(1:3, 1)), 'probe: the points'' order');
  check(isequal(cncrot_probe_plane(cw, "ORDER"), Fo) && isequal(cncrot_probe_plane(cw, [0 0 -2]), Fo) && isequal(cncrot_probe_plane(cw, [0 0 1]), Fu), 'probe: sides');
  expect_message('cncrot:badArgument', @() cncrot_probe_plane(cw, 'up'), 'probe: a side by an unknown name', 'cncrot_probe_plane', 'argument 2 (toward)');
  expect_message('cncrot:notFinite', @() cncrot_probe_plane(cw, [NaN 0 1]), 'probe: a side not finite', 'cncrot_probe_plane', 'argument 2 (toward)');
  % A whole program: every block read, each with its remark, the frames after each.
  prog = {'0 BEGIN PGM T MM', '1 TOOL CALL 1 Z S5000', '2 CYCL DEF 7.0 DATUM SHIFT', ...
          '3 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB MAX FMAX SEQ-', '4 L X+10 FMAX', '5 PLANE RESET STAY', '6 END PGM T MM'};
  [Fp, ~, frp, rp] = cncrot_program_lines('heidenhain', prog);
  check(isequal(rp, {'passed'; 'passed'; 'applied'; 'applied'; 'passed'; 'applied'; 'passed'}), 'remarks per block');
  % The same program as one text, as fileread gives it (CRLF, a final line end), and as a
  % char matrix: a line each (a helper's find: one text was read as one block, in silence).
  text = [strjoin(prog, sprintf('\r\n')) sprintf('\r\n')];
  [Ft, ~, ~, rt] = cncrot_program_lines('heidenhain', text);
  check(isequal(rt, rp) && isequal(Ft, Fp), 'program lines from one text');
  [Fm, ~, ~, rm] = cncrot_program_lines('heidenhain', char(prog));
  check(isequal(rm, rp) && isequal(Fm, Fp), 'program lines from a char matrix');
  tt = cncrot_program_translate('heidenhain', text, 'fanuc', 'G68.2');
  check(numel(tt) == numel(prog), 'translation of one text: a line each');
  % A misspelt field of a state is refused, not left out.
  expect_message('cncrot:badState', @() cncrot_program_lines('sinumerik', 'ROT X10', struct('Options', 1)), ...
                 'state: a misspelt field', 'cncrot_program_lines', 'argument 3 (state)', '''Options''');
  % Forms by the names and codes of cncrot_forms, everywhere a form is taken.
  F30 = cncrot_program_lines('fanuc', 'G68.2 X0 Y0 Z0 I0 J30 K0');
  w = cncrot_program_write('fanuc', 'G68.2', F30);
  check(isequal(cncrot_program_write('fanuc', 'g68_2', F30), w) && isequal(cncrot_program_write('fanuc', 8, F30), w), ...
        'program write: form names and codes');
  check(isequal(cncrot_program_translate('fanuc', {'G69'}, 'heidenhain', 'plane_spatial'), ...
                cncrot_program_translate('fanuc', {'G69'}, 'heidenhain', 'PLANE SPATIAL')), 'translate: form names');
  expect_message('cncrot:badArgument', @() cncrot_program_write('fanuc', 'PLANE SPATIAL', F30), ...
                 'program write: a form of another dialect', 'cncrot_program_write', 'argument 2 (form)', '''G68.2''');
  % The five-axis transformation names the argument that is not finite.
  acm = [1 1 0 0 0 0 100 0 0 0 0 0; 1 0 0 1 0 0 0 0 0 0 0 0];
  expect_message('cncrot:notFinite', @() cncrot_machine_tcp_inverse(acm, eye(4), NaN), 'tcp: L NaN', ...
                 'cncrot_machine_tcp_inverse', 'argument 3 (L)');
  expect_message('cncrot:notFinite', @() cncrot_machine_tcp_inverse(acm, eye(4), 50, [0 0 0 NaN 0 0]), 'tcp: previous NaN', ...
                 'cncrot_machine_tcp_inverse', 'argument 4 (previous)', 'element 4');
  expect_message('cncrot:notFinite', @() cncrot_machine_tcp_forward(acm, [0 0 0 30 90 0], Inf), 'tcp forward: L Inf', ...
                 'cncrot_machine_tcp_forward', 'argument 3 (L)');
  % Fanuc's rule for G53.1 (master first), by name with a blank, and as cncrot_program_axes
  % takes it for a Fanuc tilt without P: from A 5, C 0 the master A turns 25 degrees to 30.
  [~, stf] = cncrot_program_lines('fanuc', {'G68.2 X0. Y0. Z0. I0. J30. K0.', 'G53.1'});
  Ff = cncrot_program_lines('fanuc', 'G68.2 X0. Y0. Z0. I0. J30. K0.');
  am = cncrot_machine_choose(acm, Ff, [5 0 0], 'master first', 1);
  check(abs(am(1) - 30) < 1e-9 && abs(abs(am(2)) - 180) < 1e-9, 'master_first by hand');
  check(isequal(cncrot_program_axes(stf, acm, [5 0 0]), am), 'program_axes: Fanuc without P is master first');
  check(isequal(cncrot_machine_choose(acm, Ff, [5 0 0], 6, 1), am), 'master_first by code');
  % A frame's size said as it is (a helper's find: "4-by-4 or 4-by-4-by-N" for eye(3), then
  % "4-by-4" for a 4-by-4-by-2, given as "4-by-4-by-...").
  expect_message('cncrot:badSize', @() cncrot_machine_inverse(acm, eye(3)), 'frame: 3-by-3', 'cncrot_machine_inverse', 'must be 4-by-4; got a 3-by-3 double');
  expect_message('cncrot:badSize', @() cncrot_machine_inverse(acm, zeros(4, 4, 2)), 'frame: 4-by-4-by-2', 'cncrot_machine_inverse', 'got a 4-by-4-by-2 double');
  % After a direction, a block naming one rotary axis leaves the other where the machine stands.
  tp = cncrot_tool_path_lines('sinumerik', {'TRAORI', 'G1 X0 Y0 Z0 A3=0 B3=0.5 C3=0.8660254037844386', 'G1 X1 C20'}, acm, 50);
  check(abs(tp(3, 4) - 30) < 1e-9 && abs(tp(3, 5) - 20) < 1e-9, 'tool path: the letters a block leaves out stay where the machine is');
  % 'inverse' along a path: the other solution at the first row, the rows after it on its branch.
  cl3 = repmat([10 0 0 0.5 0 sqrt(3)/2], 3, 1);
  Ainv = cncrot_machine_tcp_inverse(acm, cl3, 50, [0 0 0 20 80 0], 'inverse');
  check(all(all(abs(Ainv(:, 4:5) - repmat([-30 -90], 3, 1)) < 1e-9)) && max(abs(Ainv(1, :) - Ainv(3, :))) < 1e-9, 'tcp: inverse along a path');
  % A whole program translated: datum shifts in the target's own blocks, SEQ+ as _DIR +1, cancels as
  % cancels, other blocks as they stand; the same texts as the C harness (test_program.c).
  src = {'CYCL DEF 7.0 DATUM SHIFT', 'CYCL DEF 7.1 X+10', 'CYCL DEF 7.3 Z-5', ...
         'PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX SEQ+', 'L Z+100 FMAX', 'PLANE RESET STAY'};
  [tf, rf] = cncrot_program_translate('heidenhain', src, 'fanuc', 'G68.2', 4);
  % Cycle 7's axis lines are one shift: written at the last of them (cncrot_program_joins).
  check(isequal(tf, {''; ''; 'G52 X10. Y0. Z-5.'; sprintf('G68.2 X0. Y0. Z0. I90. J30. K-90.\nG53.1'); 'L Z+100 FMAX'; 'G69'}), 'translate: into Fanuc');
  % A tilt and the block that turns to it are one PLANE ... TURN.
  tj = cncrot_program_translate('fanuc', {'G68.2 X0 Y0 Z0 I90. J30. K-90.', 'G53.1', 'G69'}, 'heidenhain', 'PLANE SPATIAL', 4);
  check(isequal(tj, {''; 'PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX'; 'PLANE RESET STAY'}), 'translate: a tilt and its turn joined');
  check(isequal(rf, {'applied'; 'applied'; 'applied'; 'applied'; 'passed'; 'applied'}), 'translate: remarks');
  % The other words of a tilt or cancel block stay, on a line of their own before the
  % translation (a retract beside G69; G1 and the feed beside a G68.2 joined to its G53.1).
  tw = cncrot_program_translate('fanuc', {'G91 G28 Z0. G69', 'N40 G1 G68.2 X0 Y0 Z0 I0 J30 K0 F300.', 'G53.1'}, 'haas', 'G268', 4);
  check(isequal(tw, {sprintf('G91 G28 Z0.\nG269'); 'N40 G1 F300.'; sprintf('G268 X0. Y0. Z0. I30. J0. K0. Q123\nG253')}), 'translate: other words kept');
  ts = cncrot_program_translate("heidenhain", src, 'SINUMERIK', "CYCLE800", int8(4));
  check(strcmp(ts{4}, sprintf('TRANS\nCYCLE800(0,"",0,57,10,0,-5,0,30,0,0,0,0,1,0,0)')) && strcmp(ts{6}, sprintf('CYCLE800()\nTRANS X=10 Y=0 Z=-5')), 'translate: into SINUMERIK, _DIR +1');
  th = cncrot_program_translate('fanuc', {'G68.2 X10 Y20 I0 J30 K0'}, 'heidenhain', 'PLANE SPATIAL', 4);
  check(isequal(th, {sprintf('CYCL DEF 7.0 DATUM SHIFT\nCYCL DEF 7.1 X+10\nCYCL DEF 7.2 Y+20\nCYCL DEF 7.3 Z+0\nPLANE SPATIAL SPA+30 SPB+0 SPC+0 STAY')}), 'translate: an origin as cycle 7');
  % A tool change's swivel to the same plane turns the axes again: written again; a datum
  % shift under a plane that turned turns nothing (no G53.1 with the plane again); the M3 of
  % the turn block is kept.
  tr = cncrot_program_translate('sinumerik', {'CYCLE800(0,"TC1",0,57,0,0,0,0,30,0,0,0,0,-1,0,0)', 'T2 M6', 'CYCLE800(0,"TC1",0,57,0,0,0,0,30,0,0,0,0,-1,0,0)'}, 'heidenhain', 'PLANE SPATIAL', 4);
  check(isequal(tr{3}, 'PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX SEQ-'), 'translate: the swivel again');
  tr = cncrot_program_translate('heidenhain', {'PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX', 'CYCL DEF 7.0 DATUM SHIFT', 'CYCL DEF 7.1 X+10'}, 'fanuc', 'G68.2', 4);
  check(isequal(tr{3}, sprintf('G69\nG52 X8.6603 Y0. Z-5.\nG68.2 X0. Y0. Z0. I90. J30. K-90.')), 'translate: a shift under a turned plane');
  tr = cncrot_program_translate('heidenhain', {'PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY', 'L B+Q121 C+Q122 R0 FMAX M3'}, 'fanuc', 'G68.2', 4);
  check(isequal(tr{2}, sprintf('M3\nG68.2 X0. Y0. Z0. I90. J30. K-90.\nG53.1')), 'translate: M3 of the turn kept');
  % TwinCAT's zero offset shift G58 is the datum its ROT turns about: carried both ways.
  tt = cncrot_program_translate('twincat', {'G58 X10 Y20 Z5', 'ROT Y30'}, 'fanuc', 'G68.2', 4);
  check(isequal(tt, {'G52 X10. Y20. Z5.'; 'G68.2 X0. Y0. Z0. I90. J30. K-90.'}), 'translate: TwinCAT G58');
  tt = cncrot_program_translate('fanuc', {'G68.2 X10 Y20 Z5 I90 J30 K-90'}, 'twincat', 'ROT', 4);
  check(isequal(tt, {sprintf('G58 X10 Y20 Z5\nROT X0 Y30 Z0')}), 'translate: into TwinCAT, the origin as G58');
  % A program's safety cancel and zero shift, with nothing active, are still written (the
  % control may have something active); a cycle's first line restates nothing.
  tc = cncrot_program_translate('heidenhain', {'PLANE RESET STAY', 'CYCL DEF 7.0 DATUM SHIFT', 'CYCL DEF 7.1 X+0', 'L Z+100 FMAX'}, 'fanuc', 'G68.2', 4);
  check(isequal(tc, {'G69'; ''; 'G52 X0. Y0. Z0.'; 'L Z+100 FMAX'}), 'translate: cancels restated');
  tc = cncrot_program_translate('heidenhain', {'PLANE RESET STAY'}, 'heidenhain', 'PLANE SPATIAL', 4);
  check(isequal(tc, {''}), 'translate: in its own dialect nothing changes');
  % An optional block stays optional: its skip mark on every line written for it (an ISO level
  % between ISO dialects; Heidenhain's digits after / are its block number).
  tk = cncrot_program_translate('fanuc', {'/2 G68.2 X10 I0 J30 K0', '/G69'}, 'sinumerik', 'CYCLE800', 4);
  check(isequal(tk, {'/2 CYCLE800(0,"",0,57,10,0,0,30,0,0,0,0,0,0,0,0)'; '/CYCLE800()'}), 'translate: skip level kept');
  tk = cncrot_program_translate('heidenhain', {'/7 PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY'}, 'fanuc', 'G68.2', 4);
  check(isequal(tk, {'/G68.2 X0. Y0. Z0. I90. J30. K-90.'}), 'translate: Heidenhain skip mark');
  tk = cncrot_program_translate('fanuc', {'/G68.2 X10 I0 J30 K0'}, 'heidenhain', 'PLANE SPATIAL', 4);
  check(numel(strfind(tk{1}, sprintf('\n/'))) == 4 && tk{1}(1) == '/', 'translate: every line marked');
  % ROT has no origin words: the origin is TRANS (which replaces the one frame), the rotation
  % AROT about it (G68.2 X10 J30 is Rx(30) about (10, 0, 0)).
  tr = cncrot_program_translate('fanuc', {'G68.2 X10 J30'}, 'sinumerik', 'ROT', 4);
  check(isequal(tr, {sprintf('TRANS X=10 Y=0 Z=0\nAROT X=30 Y=0 Z=0')}), 'translate: origin into ROT');
  expect_message('cncrot:badArgument', @() cncrot_program_translate('fanuc', {'G69'}, 'fanuc', 'PLANE SPATIAL'), 'translate: form of another dialect', 'cncrot_program_translate', 'argument 4 (form)');
  expect_message('cncrot:missingWord', @() cncrot_program_translate('heidenhain', {'L X+1', 'PLANE SPATIAL SPA+0 SPB+30'}, 'fanuc', 'G68.2'), 'translate: a refused block', 'cncrot_program_translate', 'line 2');
  % The datum shift and the choice word kept in the state; PLANE RESET keeps the shift.
  [~, st] = cncrot_program_lines('heidenhain', {'CYCL DEF 7.1 X+10', 'PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN SEQ-'});
  check(isequal(st.shift, [10 0 0]) && st.choice == 1 && st.reference_axis == 0 && isequal(st.origin, [10 0 0]) && st.positioning == 1, 'state: shift, choice and positioning (TURN)');
  [Fr, st2] = cncrot_program_lines('heidenhain', 'PLANE RESET STAY', st);
  check(isequal(Fr, [eye(3) [10; 0; 0]; 0 0 0 1]) && st2.choice == 0, 'reset keeps the shift');
  check(isequal(Fp, eye(4)) && isequal(frp(:, :, 5), frp(:, :, 4)) && abs(frp(1, 3, 4) - 0.5) < 1e-15, 'a whole program''s frames');
  % The positions a program's tilt moves a head to (C about Z carrying B about Y): Ry(30) is
  % C 0, B 30 or C 180, B -30; from C 730 the first, unwound to 720; as the machine's closest
  % choice, bit for bit. Nothing active: B 0, C free and kept.
  hd = [0 0 0 1 0 0 0 0 0 0 0 0; 0 0 1 0 0 0 150 -100 100 0 0 0];
  [~, stp] = cncrot_program_lines('heidenhain', 'PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY');
  [ax, sx] = cncrot_program_axes(stp, hd, [730 0 0]);
  check(abs(ax(1) - 720) < 1e-9 && abs(ax(2) - 30) < 1e-9 && ax(3) == 0 && sx == 0, 'program_axes');
  Fp30 = cncrot_program_lines('heidenhain', 'PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY');
  check(isequal(ax, cncrot_machine_choose(hd, Fp30, [730 0 0], 'closest')), 'program_axes is the closest choice');
  % G53.1 P2: the primary axis (C, which carries B) turns down only: from C 20 to 0, B 30.
  [Fg, stg] = cncrot_program_lines('fanuc', {'G68.2 I90 J30 K-90', 'G53.1 P2'});
  axg = cncrot_program_axes(stg, hd, [20 -25 0]);
  check(stg.choice == 5 && stg.reference_axis == 0 && abs(axg(1)) < 1e-9 && abs(axg(2) - 30) < 1e-9 && ...
        isequal(axg, cncrot_machine_choose(hd, Fg, [20 -25 0], 'negative_turn', 1)), 'program_axes under G53.1 P2');
  % The retraction and feed of the turn: MB50 along the tool axis (2), F2000 (1); CYCLE800's
  % _FR 4 is the maximum retraction (1).
  [~, stm] = cncrot_program_lines('heidenhain', 'PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB50 F2000');
  check(stm.retract == 2 && stm.retract_mm == 50 && stm.feed == 1 && stm.feed_mm_min == 2000, 'retraction and feed kept');
  [~, stc] = cncrot_program_lines('sinumerik', 'CYCLE800(4,"TC1",0,57,0,0,0,0,30,0,0,0,0,-1)');
  check(stc.retract == 1 && stc.retract_mm == 0 && stc.feed == 0, 'CYCLE800 _FR 4');
  % The working plane: G18 kept (1), ROT RPL=30 then about Y; translated, the G18 block as
  % it stands.
  [Fr, str, ~, rmr] = cncrot_program_lines('sinumerik', {'G18 G0 X0', 'ROT RPL=30'});
  c30 = cosd(30); s30 = sind(30);
  check(str.plane == 1 && isequal(rmr, {'applied'; 'applied'}) && ...
        max(max(abs(Fr(1:3, 1:3) - [c30 0 s30; 0 1 0; -s30 0 c30]))) < 1e-15, 'ROT RPL in G18');
  tr = cncrot_program_translate('fanuc', {'G18 G1 X10.', 'G68 Z0 X0 R30.', 'G69'}, 'sinumerik', 'CYCLE800');
  check(strcmp(tr{1}, 'G18 G1 X10.') && strcmp(tr{3}, 'CYCLE800()'), 'a plane selection carried across');
  [ax0, s0] = cncrot_program_axes([], hd, [730 0 0]);
  check(isequal(ax0, [730 0 0]) && s0 == 2, 'program_axes with nothing active');
  % Direct modes: PLANE AXIAL keeps the positions; its frame needs the machine: NaN without
  % one; on the head (which turns the tool frame) Rz(45)*Ry(30), by hand.
  [Fa, sta, fra] = cncrot_program_lines('heidenhain', {'PLANE SPATIAL SPA+0 SPB+30 SPC+0', 'PLANE AXIAL B+30 C+45 TURN FMAX'});
  first = fra(:, :, 1);
  check(all(isnan(Fa(:))) && ~any(isnan(first(:))) && sta.active == 2 && isequal(sta.angles, [0 30 45]) ...
        && sta.direct_given == 6 && sta.positioning == 1, 'PLANE AXIAL without a machine');
  c45 = sqrt(0.5);
  Rw = [c45 -c45 0; c45 c45 0; 0 0 1] * [sqrt(3)/2 0 0.5; 0 1 0; -0.5 0 sqrt(3)/2];
  Fm = cncrot_program_lines('heidenhain', 'PLANE AXIAL B+30 C+45 TURN FMAX', [], hd);
  check(max(max(abs(Fm(1:3, 1:3) - Rw))) < 1e-15 && isequal(Fm(1:3, 4), [0; 0; 0]), 'PLANE AXIAL on a machine');
  [axd, sd] = cncrot_program_axes(sta, hd, [730 0 0]);
  check(isequal(axd, [765 30 0]) && sd == 0, 'program_axes of PLANE AXIAL: the modulo C nearest 730');
  expect_message('cncrot:badArgument', @() cncrot_program_lines('heidenhain', 'PLANE AXIAL A+10', [], hd), ...
                 'PLANE AXIAL: an A on a head without one', 'cncrot_program_lines', 'line 1', 'argument 4 (machine)');
  bad = stp; bad.origin(1) = 1;
  expect_message('cncrot:badState', @() cncrot_program_axes(bad, hd, [0 0 0]), 'program_axes of an edited state', 'cncrot_program_axes', 'argument 1 (state)');
  expect_message('cncrot:badArgument', @() cncrot_program_axes(stp, hd, [0 0 5]), 'program_axes: a position for no axis', 'cncrot_program_axes', 'argument 3 (current)');
  [F3, st3, fr3] = cncrot_program_lines('twincat', {"N65 ROT Z30", 'N90 AROT Z15'});
  [F4, st4, fr4] = cncrot_program_lines(5, {'N65 ROT Z30', 'N90 AROT Z15'});
  check(isequal(F3, F4) && isequal(st3, st4) && isequal(fr3, fr4), 'lines as a cell with a double-quoted line');
  fm = cncrot_forms();
  check(isequal(cncrot_form_frame('g68_2', 0, [1 2 3 30 45 60]), cncrot_form_frame(fm.G68_2, 0, [1 2 3 30 45 60])), 'form g68_2');
  check(isequal(cncrot_form_frame('G68.2', int8(0), [1 2 3 30 45 60]), cncrot_form_frame(fm.G68_2, 0, [1 2 3 30 45 60])), 'form G68.2, int8 selector');
  check(isequal(cncrot_form_frame("PLANE SPATIAL", 0, [30 45 60]), cncrot_form_frame(fm.PLANE_SPATIAL, 0, [30 45 60])), 'form PLANE SPATIAL');
  check(isequal(cncrot_form_frame('g268', uint16(123), [1 2 3 0 0 0]), cncrot_form_frame(fm.G268, 123, [1 2 3 0 0 0])), 'form g268, uint16 selector');
  Fs = cncrot_form_frame(fm.PLANE_SPATIAL, 0, [30 45 60]);
  [w1, t1] = cncrot_form_values('plane_spatial', 0, Fs);
  [w2, t2] = cncrot_form_values(fm.PLANE_SPATIAL, 0, Fs);
  check(isequal(w1, w2) && isequal(t1, t2), 'form_values by name');
  fields = fieldnames(fm);
  counts = struct('CYCLE800', 9, 'SINUMERIK_ROT', 3, 'SINUMERIK_ROTS', 2, 'PLANE_SPATIAL', 3, 'PLANE_EULER', 3, ...
                  'PLANE_VECTOR', 6, 'PLANE_POINTS', 9, 'G68_2', 6, 'G158', 9, 'TWINCAT_ROT', 3, 'G268', 6, 'G68_3', 7, 'PLANE_PROJECTED', 3);
  check(isequal(sort(fieldnames(counts)), sort(fields)), 'every form has a word count here');
  for k = 1:numel(fields)
    w = ones(1, counts.(fields{k}));
    for sel = [0 1 57 123]
      check(isequal(outcome(@() cncrot_form_frame(lower(fields{k}), sel, w)), outcome(@() cncrot_form_frame(fm.(fields{k}), sel, w))), ...
            sprintf('form by name: %s, selector %d', lower(fields{k}), sel));
    end
  end
  head = [0 0 0 1 0 0 0 0 0 0 0 0; 0 0 1 0 0 0 150 -100 100 0 0 0];
  F = cncrot_machine_forward(head, [30 40 0]);
  rules = {'closest', 0, 0; 'minus', 1, 2; 'plus', 2, 2; 'inverse', 3, 0; 'positive_turn', 4, 1; 'negative_turn', 5, 2};
  for k = 1:size(rules, 1)
    [x1, r1, e1, s1] = cncrot_machine_choose(head, F, [10 0 0], rules{k, 2}, rules{k, 3});
    [x2, r2, e2, s2] = cncrot_machine_choose(head, F, [10 0 0], rules{k, 1}, int8(rules{k, 3}));
    [x3, r3, e3, s3] = cncrot_machine_choose(head, F, [10 0 0], upper(rules{k, 1}), uint32(rules{k, 3}));
    check(isequal({x1, r1, e1, s1}, {x2, r2, e2, s2}, {x3, r3, e3, s3}), ['rule by name: ' rules{k, 1}]);
  end
  check(isequal(cncrot_machine_choose(head, F, [0 0 0], "minus", 2), cncrot_machine_choose(head, F, [0 0 0], 1, 2)), 'rule as a double-quoted name');
  check(isequal(cncrot_program_lines('sinumerik', 'ROT Z30 X20', struct('options', int32(1))), ...
                cncrot_program_lines(1, 'ROT Z30 X20', struct('options', 1))), 'state options of class int32');
  check(isequal(cncrot_program_lines('sinumerik', 'ROT Z30 X20', struct('options', true)), ...
                cncrot_program_lines(1, 'ROT Z30 X20', struct('options', 1))), 'state options logical');
  expect_message('cncrot:badState', @() cncrot_program_lines('sinumerik', 'ROT Z30', struct('options', uint8(4))), 'state options uint8 4', ...
                 'cncrot_program_lines', 'argument 3 (state)');
  % Refusals: the identifier, the function, the argument, what it must be, what was given.
  expect_message('cncrot:badSequence', @() cncrot_convert(0, 'ZQY', [30 45 60], 1, 39), 'unknown letter', 'cncrot_convert', ...
                 'argument 2 (sequence_in) must be an axis sequence such as ''ZXY'' or a code 0..63; got ''ZQY''');
  expect_message('cncrot:badSequence', @() cncrot_convert(0, "ZQY", [30 45 60], 1, 39), 'unknown letter in a string', 'cncrot_convert', 'argument 2 (sequence_in)', '''ZQY''');
  expect_message('cncrot:badSequence', @() cncrot_convert(0, 'ZZY', [30 45 60], 1, 39), 'repeated letter', 'cncrot_convert', 'argument 2 (sequence_in)', 'repeats');
  expect_message('cncrot:badSequence', @() cncrot_convert(0, 'XY', [30 45 60], 1, 39), 'two letters', 'cncrot_convert', 'argument 2 (sequence_in)', '''XY''');
  expect_message('cncrot:badSequence', @() cncrot_convert(0, 'XYZX', [30 45 60], 1, 39), 'four letters', 'cncrot_convert', 'argument 2 (sequence_in)');
  expect_message('cncrot:badSequence', @() cncrot_convert(0, '', [30 45 60], 1, 39), 'no letters', 'cncrot_convert', 'argument 2 (sequence_in)');
  expect_message('cncrot:badSequence', @() cncrot_convert(0, 57, [30 45 60], 1, 'X-Y-Z'), 'separators', 'cncrot_convert', 'argument 5 (sequence_out)', '''X-Y-Z''');
  expect_message('cncrot:badSequence', @() cncrot_matrix(1, 64, [1 2 3]), 'code 64', 'cncrot_matrix', 'argument 2 (sequence)', 'got 64');
  expect_message('cncrot:badSequence', @() cncrot_matrix(1, int8(22), [1 2 3]), 'int8 code 22', 'cncrot_matrix', 'argument 2 (sequence)', 'got 22', 'YXX');
  expect_message('cncrot:badSequence', @() cncrot_matrix(1, uint64(2)^40, [1 2 3]), 'uint64 code 2^40', 'cncrot_matrix', 'argument 2 (sequence)', 'got 1099511627776');
  expect_message('cncrot:badArgument', @() cncrot_matrix(1, 57.5, [1 2 3]), 'fractional code', 'cncrot_matrix', 'argument 2 (sequence)', 'got 57.5');
  expect_message('cncrot:badArgument', @() cncrot_matrix(1, single(1.5), [1 2 3]), 'fractional single code', 'cncrot_matrix', 'argument 2 (sequence)', 'got 1.5');
  expect_message('cncrot:badClass', @() cncrot_matrix(1, {57}, [1 2 3]), 'cell code', 'cncrot_matrix', 'argument 2 (sequence)', 'cell');
  expect_message('cncrot:badSize', @() cncrot_matrix(1, [57 39], [1 2 3]), 'two codes', 'cncrot_matrix', 'argument 2 (sequence)', 'scalar');
  expect_message('cncrot:badSize', @() cncrot_matrix(1, ['XYZ'; 'ZXY'], [1 2 3]), 'char matrix sequence', 'cncrot_matrix', 'argument 2 (sequence)');
  expect_message('cncrot:incompleteSequence', @() cncrot_convert(0, 57, [30 45 60], 1, 'X0Z'), 'X0Z out', 'cncrot_convert', 'argument 5 (sequence_out)', 'three rotations', '''X0Z''');
  expect_message('cncrot:incompleteSequence', @() cncrot_angles('intrinsic', 3, eye(3)), 'code 3 to decompose', 'cncrot_angles', 'argument 2 (sequence)', 'got 3');
  expect_message('cncrot:incompleteSequence', @() cycle600(0, 'H', 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 'Z0X', 0,0,0), 'cycle600 _BIN_OUT', 'cycle600', 'argument 15 (_BIN_OUT)');
  expect_message('cncrot:badFlag', @() cncrot_convert('sideways', 57, [30 45 60], 1, 39), 'unknown convention', 'cncrot_convert', ...
                 'argument 1 (intrinsic_in) must be ''intrinsic'', ''extrinsic'', 1 or 0; got ''sideways''');
  expect_message('cncrot:badFlag', @() cncrot_convert(0, 57, [30 45 60], "intrinsics", 39), 'misspelt convention', 'cncrot_convert', 'argument 4 (intrinsic_out)', '''intrinsics''');
  expect_message('cncrot:badFlag', @() cncrot_matrix(int16(2), 57, [1 2 3]), 'int16 flag 2', 'cncrot_matrix', 'argument 1 (intrinsic)', 'got 2');
  expect_message('cncrot:badFlag', @() cncrot_matrix(-1, 57, [1 2 3]), 'flag -1', 'cncrot_matrix', 'argument 1 (intrinsic)', 'got -1');
  expect_message('cncrot:badFlag', @() cncrot_matrix(Inf, 57, [1 2 3]), 'flag Inf', 'cncrot_matrix', 'argument 1 (intrinsic)', 'got Inf');
  expect_message('cncrot:badArgument', @() cncrot_matrix(0.5, 57, [1 2 3]), 'flag 0.5', 'cncrot_matrix', 'argument 1 (intrinsic)', 'got 0.5');
  expect_message('cncrot:badArgument', @() cncrot_matrix(NaN, 57, [1 2 3]), 'flag NaN', 'cncrot_matrix', 'argument 1 (intrinsic)', 'got NaN');
  expect_message('cncrot:complex', @() cncrot_matrix(complex(1, 1), 57, [1 2 3]), 'complex flag', 'cncrot_matrix', 'argument 1 (intrinsic)');
  expect_message('cncrot:badClass', @() cncrot_matrix(1, 57, int8([1 2 3])), 'int8 angles', 'cncrot_matrix', 'argument 3 (angles)', 'double');
  expect_message('cncrot:badFlag', @() cycle600(0, 'H', 2, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 0,0,0), 'cycle600 _SW_REC 2', 'cycle600', 'argument 3 (_SW_REC)');
  expect_message('cncrot:badFlag', @() cycle600(0, 'H', 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 0,2,0), 'cycle600 _ROT_INV 2', 'cycle600', 'argument 17 (_ROT_INV)');
  expect_message('cncrot:badFlag', @() cycle600('intrinsically', 'H', 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 0,0,0), 'cycle600 _INEXIN', 'cycle600', 'argument 1 (_INEXIN)');
  expect_message('cncrot:badSequence', @() cycle600(0, 'H', 1, 'XXY', 0,0,0, 1,2,3, 0,0,0, 1, 39, 0,0,0), 'cycle600 _BIN_IN', 'cycle600', 'argument 4 (_BIN_IN)', '''XXY''');
  expect_message('cncrot:nameTooLong', @() cycle600(0, repmat('A', 1, 40), 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 0,0,0), 'cycle600 long name', 'cycle600', 'argument 2 (_MIHEAD)');
  expect_message('cncrot:badClass', @() cycle600(0, 'H', 1, 57, 0,0,0, 1,2,3, 0,0,0, 1, 39, 1,0,0, 7), 'cycle600 previous gud', 'cycle600', 'argument 19 (previous gud)');
  expect_message('cncrot:badArgument', @() cncrot_program_lines('klingon', 'G69'), 'unknown dialect', 'cncrot_program_lines', ...
                 'argument 1 (dialect) must be a dialect', '''heidenhain''', 'got ''klingon''');
  expect_message('cncrot:badArgument', @() cncrot_program_lines(int8(9), 'G69'), 'dialect 9', 'cncrot_program_lines', 'argument 1 (dialect)', 'got 9');
  expect_message('cncrot:badArgument', @() cncrot_program_lines(2.5, 'G69'), 'dialect 2.5', 'cncrot_program_lines', 'argument 1 (dialect)', 'got 2.5');
  expect_message('cncrot:badArgument', @() cncrot_program_write("siemens", 'ROT', eye(4)), 'unknown dialect, write', 'cncrot_program_write', 'argument 1 (dialect)', '''siemens''');
  expect_message('cncrot:badArgument', @() cncrot_program_write('fanuc', 'PLANE SPATIAL', eye(4)), 'form of another dialect', 'cncrot_program_write', 'argument 2 (form)');
  expect_message('cncrot:badArgument', @() cncrot_program_write('fanuc', 'G68.2', eye(4), 18), 'decimals 18', 'cncrot_program_write', 'argument 4 (decimals)', 'got 18');
  expect_message('cncrot:hasOrigin', @() cncrot_program_write('heidenhain', 'PLANE SPATIAL', [eye(3) [1; 2; 3]; 0 0 0 1]), 'origin for SPATIAL', 'cncrot_program_write', 'argument 3 (F)');
  expect_message('cncrot:notANumber', @() cncrot_program_lines('heidenhain', {'PLANE RESET', 'PLANE SPATIAL SPA+Q120 SPB+0 SPC+0'}), 'line and column', ...
                 'cncrot_program_lines', 'argument 2 (lines), line 2, column 19 (''Q120'')');
  expect_message('cncrot:missingWord', @() cncrot_program_lines('heidenhain', 'PLANE SPATIAL SPA+10 SPB+0'), 'missing word named', ...
                 'cncrot_program_lines', 'line 1, column 27 (missing: SPC)');
  expect_message('cncrot:badArgument', @() cncrot_program_lines('sinumerik', 'CYCLE600(0,"A B",1,57,0,0,0,30,45,60,0,0,0,1,39)'), ...
                 'parameter named', 'cncrot_program_lines', 'column 12 (_MIHEAD: empty, or at most 31');
  expect_message('cncrot:badClass', @() cncrot_program_lines('fanuc', 42), 'numeric line', 'cncrot_program_lines', 'argument 2 (lines)');
  expect_message('cncrot:badState', @() cncrot_program_lines('fanuc', 'G69', struct('active', 2)), 'bad state', 'cncrot_program_lines', 'argument 3 (state)');
  expect_message('cncrot:badArgument', @() cncrot_machine_choose(head, F, [0 0 0], 'sideways'), 'unknown rule', 'cncrot_machine_choose', ...
                 'argument 4 (rule) must be a rule', '''minus''', 'got ''sideways''');
  expect_message('cncrot:badArgument', @() cncrot_machine_choose(head, F, [0 0 0], 7), 'rule 7', 'cncrot_machine_choose', 'argument 4 (rule)', 'got 7');
  expect_message('cncrot:badArgument', @() cncrot_machine_choose(head, F, [0 0 0], 'minus'), 'minus without an axis', 'cncrot_machine_choose', 'argument 5 (ref)', 'got 0');
  expect_message('cncrot:badArgument', @() cncrot_machine_choose(head, F, [0 0 0], 'plus', 3), 'plus on a missing axis', 'cncrot_machine_choose', 'argument 5 (ref)', 'got 3');
  expect_message('cncrot:badArgument', @() cncrot_machine_choose(head, F, [0 0 0], 'closest', 1), 'closest with an axis', 'cncrot_machine_choose', 'argument 5 (ref)', 'got 1');
  expect_message('cncrot:badArgument', @() cncrot_machine_choose(head, F, [0 0 7], 'closest'), 'unused axis moved', 'cncrot_machine_choose', 'argument 3 (current)', 'axis 3');
  expect_message('cncrot:badArgument', @() cncrot_machine_choose(head, F, [0 0 0], 'minus', 1.5), 'fractional axis', 'cncrot_machine_choose', 'argument 5 (ref)', 'got 1.5');
  expect_message('cncrot:parse', @() cncrot_machine_forward('$TC_CARR7[1]=1x', [0 0 0]), 'swivel text', 'cncrot_machine_forward', 'argument 1 (machine), swivel data line 1');
  expect_message('cncrot:badArgument', @() cncrot_form_frame('g68.9', 0, [1 2 3]), 'unknown form', 'cncrot_form_frame', ...
                 'argument 1 (form) must be a form', '''g68_2''', 'got ''g68.9''');
  expect_message('cncrot:badArgument', @() cncrot_form_values(99, 0, eye(4)), 'form 99', 'cncrot_form_values', 'argument 1 (form)', 'got 99');
  expect_message('cncrot:hasOrigin', @() cncrot_form_values('plane_spatial', 0, [eye(3) [10; 0; 0]; 0 0 0 1]), 'origin for PLANE SPATIAL', 'cncrot_form_values', 'shift the datum first');
  expect_message('cncrot:badArgument', @() cncrot_form_frame('plane_spatial', 5, [0 0 0]), 'selector 5', 'cncrot_form_frame', 'argument 2 (selector)');
  expect_message('cncrot:badArgument', @() cncrot_form_frame('plane_spatial', 0.5, [0 0 0]), 'selector 0.5', 'cncrot_form_frame', 'argument 2 (selector)', 'got 0.5');
  expect_message('cncrot:notFinite', @() cncrot_matrix('intrinsic', 'XYZ', [1 2 3; 4 NaN 6]), 'row named', 'cncrot_matrix', 'argument 3 (angles), row 2:');
  expect_message('cncrot:notARotation', @() cncrot_angles(1, 'XYZ', cat(3, eye(3), 2 * eye(3))), 'matrix named', 'cncrot_angles', 'argument 3 (R), matrix 2:');
  expect_message('cncrot:nargin', @() cncrot_convert(0, 'XYZ', [1 2 3]), 'nargin', 'cncrot_convert', 'not enough input arguments');

  % The toolbox's help: Contents.m lists every function, every help text has See also, and
  % cycle600's says what _SW_REC = 0 does now (recalculates; no cncrot:notAvailable).
  here = fileparts(fileparts(mfilename('fullpath')));
  contents = fileread(fullfile(here, 'Contents.m'));
  files = dir(fullfile(here, '*.m'));
  for k = 1:numel(files)
    [~, fname] = fileparts(files(k).name);
    if strcmp(fname, 'Contents'), continue; end
    check(~isempty(regexp(contents, ['\n%\s+' fname '\s+- '], 'once')), ['Contents.m lists ' fname]);
    check(~isempty(strfind(fileread(fullfile(here, files(k).name)), 'See also')), ['See also in ' fname]);
  end
  c600 = fileread(fullfile(here, 'cycle600.m'));
  check(isempty(strfind(c600, 'notAvailable')) && ~isempty(strfind(c600, 'SW_REC = 0')), 'cycle600 help: _SW_REC = 0');

  % The dialects' forms: a worked number of docs/dialects.md, batches, errors, empty input.
  fm = cncrot_forms();
  F = cncrot_form_frame(fm.PLANE_SPATIAL, 0, [45 0 90]);
  check(max(max(abs(F(1:3, 1:3) - [0 -0.707107 0.707107; 1 0 0; 0 0.707107 0.707107]))) < 5e-7, 'PLANE SPATIAL 45 0 90');
  F2 = cncrot_form_frame(fm.G68_2, 0, [1 2 3 30 45 60; 0 0 0 0 30 0]);
  check(isequal(size(F2), [4 4 2]) && isequal(F2(1:3, 4, 1), [1; 2; 3]), 'G68.2 batch');
  [w, st] = cncrot_form_values(fm.G68_2, 0, F2);
  check(max(max(abs(w - [1 2 3 30 45 60; 0 0 0 0 30 0]))) < 1e-12 && isequal(st, [0; 0]), 'G68.2 round trip');
  [w, st] = cncrot_form_values(fm.PLANE_SPATIAL, 0, cncrot_form_frame(fm.PLANE_SPATIAL, 0, 0:90:180));
  check(st == 1 && w(3) == 0, 'PLANE SPATIAL singular');
  check(isequal(size(cncrot_form_frame(fm.G268, 123, zeros(0, 6))), [4 4 0]), 'empty forms');
  check(isequal(size(cncrot_form_values(fm.G268, 123, zeros(4, 4, 0))), [0 6]), 'empty words');
  expect_error('cncrot:badArgument', @() cncrot_form_frame(99, 0, [1 2 3]), 'unknown form');
  expect_error('cncrot:badSize', @() cncrot_form_frame(fm.G68_2, 0, [1 2 3]), 'wrong word count');
  expect_error('cncrot:badSequence', @() cncrot_form_frame(fm.G268, 313, zeros(0, 6)), 'bad Q, empty');
  expect_error('cncrot:notAvailable', @() cncrot_form_frame(fm.CYCLE800, 192, zeros(1, 9)), 'direct mode');
  expect_error('cncrot:coincident', @() cncrot_form_frame(fm.PLANE_POINTS, 0, zeros(1, 9)), 'coincident points');
  expect_error('cncrot:badArgument', @() cncrot_form_values(fm.SINUMERIK_ROTS, 0, eye(4)), 'ROTS not writable');
  expect_error('cncrot:hasOrigin', @() cncrot_form_values(fm.PLANE_SPATIAL, 0, [eye(3) [1; 0; 0]; 0 0 0 1]), 'origin for SPATIAL');
  expect_error('cncrot:notARotation', @() cncrot_form_values(fm.G68_2, 0, 2 * eye(4)), 'not a frame');
  expect_error('cncrot:badSize', @() cncrot_form_values(fm.G68_2, 0, eye(3)), 'F size');

  % Probing: the paper's flange (extrinsic X 30, Y 45), a plane, an edge, the refusals.
  R = cncrot_matrix(0, 57, [30 45 0]);
  nz = R(:, 3);
  z = @(x, y) 50 - (nz(1) * x + nz(2) * y) / nz(3);
  [a, F] = cncrot_probe_flange([10 20 z(10, 20)], [110 20 z(110, 20)], [10 20 z(10, 20)], [10 90 z(10, 90)]);
  check(max(abs(a - [30 45 0])) < 1e-12 && max(max(abs(F(1:3, 1:3) - R))) < 1e-15, 'paper flange');
  [F, fl, rm] = cncrot_probe_plane([0 0 5; 100 0 5; 0 100 5; 100 100 5]);
  check(fl < 1e-12 && rm < 1e-12 && abs(F(3, 3) - 1) < 1e-15, 'level plane');
  check(abs(cncrot_probe_edge(eye(4), [0 0 0], [100 100 0]) - 45) < 1e-12, 'edge 45');
  expect_error('cncrot:coincident', @() cncrot_probe_flange([0 0 0], [0 0 0], [0 0 0], [0 1 0]), 'flange A1 = A2');
  expect_error('cncrot:collinear', @() cncrot_probe_flange([0 0 0], [1 0 0], [0 0 0], [-1 0 0]), 'flange parallel');
  expect_error('cncrot:tooFew', @() cncrot_probe_plane([0 0 0; 1 0 0]), 'two points');
  expect_error('cncrot:collinear', @() cncrot_probe_plane([0 0 0; 1 1 1; 2 2 2]), 'points on a line');
  expect_error('cncrot:collinear', @() cncrot_probe_edge(eye(4), [0 0 0], [0 0 5]), 'edge along the normal');
  expect_error('cncrot:badSize', @() cncrot_probe_flange([0 0], [1 0 0], [0 0 0], [0 1 0]), 'point size');

  % Program lines: the vendors' lines, refusals with their columns, the writer read back.
  d = cncrot_dialects();
  F = cncrot_program_lines(d.TWINCAT, {'N65 ROT Z30', 'N90 AROT Z15 (add)'});
  c = cosd(45);
  check(max(max(abs(F - [c -c 0 0; c c 0 0; 0 0 1 0; 0 0 0 1]))) < 1e-15, 'TwinCAT ROT Z30, AROT Z15');
  [F, st, fr] = cncrot_program_lines(d.SYNTEC, {'G158 L3 P01159 X0 Y0 Z0 A0 B0 C10 U0 V0 W0', 'G158 L3 P01159 X0 Y0 Z0 A0 B0 C10 U0 V0 W0'});
  check(abs(F(2, 1) - sind(20)) < 1e-15 && isequal(size(fr), [4 4 2]) && abs(fr(2, 1, 1) - sind(10)) < 1e-15, 'Syntec increments');
  F2 = cncrot_program_lines(d.SYNTEC, 'G69', st);
  check(isequal(F2, eye(4)), 'state carried into the next call');
  F = cncrot_program_lines(d.HEIDENHAIN, '5 PLANE SPATIAL SPA+27 SPB+0 SPC+45 TURN MB MAX FMAX SEQ-');
  check(max(max(abs(F(1:3, 1:3) - [0.707107 -0.630037 0.321020; 0.707107 0.630037 -0.321020; 0 0.453990 0.891007]))) < 1e-6, 'PLANE SPATIAL worked numbers');
  F = cncrot_program_lines(d.SINUMERIK, 'ROT X10 Y90 Z40');
  check(strcmp(cncrot_program_write(d.SINUMERIK, 'ROT', F, 4), 'ROT X=0 Y=90 Z=30'), 'SINUMERIK read-back');
  % (Two tilted frames: how the identity is written, a G68.2 of zeros or the cancel G69, is
  % the library's choice and not this test's.)
  F1 = cncrot_program_lines(d.FANUC, 'G68.2 X1. Y2. Z3. I30. J0. K0.');
  ls = cncrot_program_write(d.FANUC, 'G68.2', cat(3, F1, F), 3);
  check(iscell(ls) && numel(ls) == 2 && strcmp(ls{1}, 'G68.2 X1. Y2. Z3. I30. J0. K0.'), 'two frames, two lines');
  check(isequal(cncrot_program_lines(d.FANUC, ls{2}), F) || max(max(abs(cncrot_program_lines(d.FANUC, ls{2}) - F))) < 1e-6, 'written line reads back');
  expect_error('cncrot:notANumber', @() cncrot_program_lines(d.SINUMERIK, 'ROT X=R1'), 'variable');
  expect_error('cncrot:unknownWord', @() cncrot_program_lines(d.HAAS, 'G268 Q123 Y1 Y2'), 'repeated word');
  expect_error('cncrot:missingWord', @() cncrot_program_lines(d.HAAS, 'G268 X0'), 'missing Q');
  expect_error('cncrot:lineTooLong', @() cncrot_program_lines(d.FANUC, ['G69 (' repmat('x', 1, 300) ')']), 'long line');
  try
    cncrot_program_lines(d.HEIDENHAIN, {'PLANE RESET', 'PLANE SPATIAL SPA+Q120 SPB+0 SPC+0'});
    check(false, 'column reported');
  catch err
    check(~isempty(strfind(err.message, 'line 2, column 19')), ['column reported: ' err.message]);
  end
  % G68.3: the plane of the tool direction where the machine stands, which the program does not
  % state: not followed, the frame unchanged (a malformed one still refused).
  [F3, ~, ~, r3] = cncrot_program_lines(d.FANUC, {'G68.2 X0 Y0 Z0 I0 J30 K0', 'G68.3 X0 Y0 Z0 R0'});
  check(isequal(r3, {'applied'; 'not followed'}) && isequal(F3, cncrot_program_lines(d.FANUC, 'G68.2 X0 Y0 Z0 I0 J30 K0')), 'G68.3 not followed');
  expect_error('cncrot:unknownWord', @() cncrot_program_lines(d.FANUC, 'G68.3 R0 A1'), 'G68.3 with a word it has not');
  expect_error('cncrot:badArgument', @() cncrot_program_lines(9, 'G69'), 'bad dialect');
  expect_error('cncrot:badState', @() cncrot_program_lines(d.FANUC, 'G69', struct('active', 2)), 'bad state');
  % The state is sealed: an edited field is refused; options start a new program.
  [~, st] = cncrot_program_lines(d.FANUC, 'G68.2 X10 I0 J30 K0');
  check(st.origin(1) == 10 && st.seal ~= 0, 'sealed state');
  st.origin(1) = 14;
  expect_error('cncrot:badState', @() cncrot_program_lines(d.FANUC, 'G69', st), 'edited state');
  F = cncrot_program_lines(d.SINUMERIK, 'ROT Z30 X20', struct('options', 1));
  check(max(max(abs(F(1:3, 1:3) - [cosd(30) -sind(30)*cosd(20) sind(30)*sind(20); sind(30) cosd(30)*cosd(20) -cosd(30)*sind(20); 0 sind(20) cosd(20)]))) < 1e-15, 'Euler mode from options');
  expect_error('cncrot:badState', @() cncrot_program_lines(d.SINUMERIK, 'ROT Z30', struct('options', 4)), 'unknown option');
  % TABLE ROT is kept in the state (and cleared by a reset).
  [~, st] = cncrot_program_lines(d.HEIDENHAIN, 'PLANE SPATIAL SPA+0 SPB+0 SPC+90 TURN TABLE ROT');
  check(st.table_rot == 1, 'TABLE ROT in the state');
  % On a table C (about Z) with a head B (about Y) the tool stays vertical and C is free:
  % TABLE ROT turns the table, Rz(-C) = Rz(90) by hand, so C = -90; COORD ROT keeps it.
  tc = [1 0 0 1 0 0 0 0 0 0 0 0; 0 0 1 0 0 0 0 0 0 0 0 0];
  axt = cncrot_program_axes(st, tc, [0 0 0]);
  check(abs(axt(1) + 90) < 1e-9 && abs(axt(2)) < 1e-9, 'program_axes turns the table (TABLE ROT)');
  [~, stc] = cncrot_program_lines(d.HEIDENHAIN, 'PLANE SPATIAL SPA+0 SPB+0 SPC+90 TURN COORD ROT');
  axc = cncrot_program_axes(stc, tc, [20 0 0]);
  check(abs(axc(1) - 20) < 1e-9, 'program_axes keeps the table (COORD ROT)');
  [~, st] = cncrot_program_lines(d.HEIDENHAIN, 'PLANE RESET STAY', st);
  check(st.table_rot == 0, 'TABLE ROT cleared by the reset');
  % An incremental tilt is kept as one and translated into the target's incremental form
  % (SPC+15 is Rz(15), G68.2's I15 J0 K0).
  [~, st] = cncrot_program_lines(d.HEIDENHAIN, {'PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY', 'PLANE RELATIV SPC+15 STAY'});
  check(st.relative == 1, 'PLANE RELATIV in the state');
  t = cncrot_program_translate(d.HEIDENHAIN, {'PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY', 'PLANE RELATIV SPC+15 STAY'}, d.FANUC, 'G68.2');
  check(strcmp(t{2}, 'G68.4 X0. Y0. Z0. I15. J0. K0.'), 'PLANE RELATIV as G68.4');
  % Cycle 19: spatial angles by default (Ry(30)), the rotary positions with option 2.
  F = cncrot_program_lines(d.HEIDENHAIN, {'CYCL DEF 19.0 WORKING PLANE', 'CYCL DEF 19.1 B+30'});
  check(max(max(abs(F(1:3, 1:3) - [cosd(30) 0 sind(30); 0 1 0; -sind(30) 0 cosd(30)]))) < 1e-15, 'cycle 19 spatial');
  [~, st] = cncrot_program_lines(d.HEIDENHAIN, 'CYCL DEF 19.1 B+30 C+45', struct('options', 2));
  check(st.active == 2 && isequal(st.angles(:).', [0 30 45]), 'cycle 19 axis angles');
  expect_error('cncrot:badArgument', @() cncrot_program_write(d.FANUC, 'PLANE SPATIAL', eye(4)), 'form of another dialect');
  expect_error('cncrot:badClass', @() cncrot_program_lines(d.FANUC, 42), 'numeric line');
  check(isequal(size(cncrot_program_write(d.FANUC, 'G68.2', zeros(4, 4, 0))), [0 1]), 'no frames, no lines');

  % Parity with the C harness, bit for bit.
  % The machines of c_tests/parity.c: a fork head and a table with a two-axis head.
  machines = {[0 0 0 1 0 0 0 0 0 0 0 0; 0 0 1 0 0 0 150 -100 100 0 0 0], ...
              [1 0 0 1 500 300 0 0 0 0 0 0; 0 0 1 0 0 0 540 -120 120 0 0 0; 0 1 0 0 0 0 250 0 0 0 0 0]};
  head = machines{1};
  F = cncrot_machine_forward(head, [30 40 0]);
  check(abs(F(1, 3) - cosd(30) * sind(40)) < 1e-15 && abs(F(3, 3) - cosd(40)) < 1e-15, 'machine: tool direction by hand');
  S = cncrot_machine_inverse(head, F);
  check(size(S, 1) == 2 && any(all(abs(S - [30 40 0]) < 1e-9, 2)) && any(all(abs(S - [-150 -40 0]) < 1e-9, 2)), 'machine: both solutions');
  check(all(abs(cncrot_machine_choose(head, F, [750 0 0]) - [750 40 0]) < 1e-9), 'machine: unwinding 750');
  check(all(abs(cncrot_machine_choose(head, F, [0 0 0], 1, 2) - [-150 -40 0]) < 1e-9), 'machine: minus on B');
  expect_error('cncrot:unreachable', @() cncrot_machine_inverse([0 0 0 1 0 0 0 0 0 0 0 0], [1 0 0 0; 0 0 -1 0; 0 1 0 0; 0 0 0 1]), 'machine: unreachable');
  expect_error('cncrot:outOfTravel', @() cncrot_machine_choose([0 0 0 1 0 0 0 0 0 0 0 0; 0 0 1 0 0 0 150 -10 10 0 0 0], F, [0 0 0]), 'machine: travel');
  expect_error('cncrot:parse', @() cncrot_machine_forward('$TC_CARR7[1]=1x', [0 0 0]), 'machine: swivel text');
  carr = sprintf('$TC_CARR7[1]=0 $TC_CARR8[1]=0 $TC_CARR9[1]=1\n$TC_CARR10[1]=0 $TC_CARR11[1]=1 $TC_CARR12[1]=0\n$TC_CARR6[1]=-150\n');
  check(max(max(abs(cncrot_machine_forward(carr, [30 40 0]) - F))) < 1e-12, 'machine: swivel text = matrix');
  % The five-axis transformation: the AC table of docs/kinematics.md, by hand.
  ac = [1 1 0 0 0 0 100 0 0 0 0 0; 1 0 0 1 0 0 0 0 0 0 0 0];
  want = [0, 50 + 5 * sqrt(3), 155 - 50 * sqrt(3), 30, 90, 0];
  A = cncrot_machine_tcp_inverse(ac, [10 0 0 0.5 0 sqrt(3)/2], 50, [0 0 0 20 80 0]);
  check(max(abs(A - want)) < 1e-12, 'tcp: AC table by hand (CL row)');
  P = cncrot_machine_tcp_forward(ac, want, 50);
  check(max(abs(P(1:3, 4) - [10; 0; 0])) < 1e-12 && max(abs(P(1:3, 3) - [0.5; 0; sqrt(3)/2])) < 1e-15, 'tcp: forward by hand');
  check(max(abs(cncrot_machine_tcp_inverse(ac, P, 50, [0 0 0 20 80 0]) - want)) < 1e-12, 'tcp: a pose as input');
  % A path through the pole in the plane of A: C stays at 37, A passes 0 (free there).
  a = (10:-0.5:-10).';
  axes_in = [repmat([5 6 7], numel(a), 1), a, repmat([37 0], numel(a), 1)];
  Ps = cncrot_machine_tcp_forward(ac, axes_in, 80);
  [As, st] = cncrot_machine_tcp_inverse(ac, Ps, 80, axes_in(1, :));
  check(max(max(abs(As - axes_in))) < 1e-9 && isequal(st.', double(a.' == 0) * 2), 'tcp: path through the pole');
  check(isequal(size(cncrot_machine_tcp_inverse(ac, zeros(0, 6), 50)), [0 6]), 'tcp: no rows');
  low = cncrot_machine_tcp_inverse(ac, [10 0 0 0.5 0 sqrt(3)/2], 50, [0 0 0 20 80 0], 'minus', 1);
  check(abs(low(4) + 30) < 1e-12 && abs(low(5) + 90) < 1e-12, 'tcp: A the priority axis, its lower position');
  expect_error('cncrot:badArgument', @() cncrot_machine_tcp_inverse(ac, [10 0 0 0.5 0 sqrt(3)/2], 50, zeros(1, 6), 'minus', 3), 'tcp: ref beyond the axes');
  % 'e' and 'i' as the command line takes them.
  check(isequal(cncrot_convert('e', 'XYZ', [30 45 60], 'i', 'ZXY'), cncrot_convert('extrinsic', 'XYZ', [30 45 60], 'intrinsic', 'ZXY')), ...
        'convert: e and i abbreviations');
  Pc = cncrot_cl_pose([10 20 5 0 0 2; 1 2 3 -3 0 0]);
  check(isequal(Pc(:, :, 1), [eye(3) [10; 20; 5]; 0 0 0 1]) && isequal(Pc(1:3, 3, 2), [-1; 0; 0]) && isequal(Pc(1:3, 1, 2), [0; 1; 0]), ...
        'cl_pose: along Z, and along -X (X'' from Y)');
  expect_message('cncrot:badArgument', @() cncrot_cl_pose([1 2 3 0 0 0]), 'cl_pose: zero direction', 'cncrot_cl_pose', 'must not be zero');
  % Carried: from the tool tilted 60 degrees about Y to +X, X' turns 60 degrees about Y
  % with it, (sqrt 3 / 2, 0, -1/2) to (0, 0, -1); the next row, +X again, keeps it.
  Q = cncrot_cl_pose([1 2 3 3 0 0; 4 5 6 1 0 0], cncrot_cl_pose([0 0 0 1 0 sqrt(3)]));
  check(max(abs(Q(1:3, 1, 1) - [0; 0; -1])) < 1e-15 && max(max(abs(Q(1:3, 1:3, 2) - Q(1:3, 1:3, 1)))) < 1e-15 && isequal(Q(1:3, 4, 2), [4; 5; 6]), ...
        'cl_pose: X'' carried from P0, then from the row before');
  expect_message('cncrot:notARotation', @() cncrot_cl_pose([1 2 3 0 0 1], 2 * eye(4)), 'cl_pose: P0 no rotation', 'cncrot_cl_pose', 'P0');
  expect_error('cncrot:badSize', @() cncrot_cl_pose([1 2 3 0 0 1], eye(3)), 'cl_pose: P0 of 3-by-3');
  % Three rotary axes (a C table, a B and an A head): CL rows whose i passes 0.9 turn
  % every axis a little, not by tens of degrees.
  three = [1 0 0 1 0 0 0 0 0 0 0 0; 0 0 1 0 0 150 0 0 0 0 0 0; 0 1 0 0 0 100 0 0 0 0 0 0];
  A3 = cncrot_machine_tcp_inverse(three, [0 0 0 0.899 0.1 0.4264; 0 0 0 0.901 0.1 0.4222], 30);
  check(max(abs(A3(2, 4:6) - A3(1, 4:6))) < 1, 'tcp: three axes continuous across |i| = 0.9');
  expect_message('cncrot:badArgument', @() cncrot_machine_tcp_inverse(ac, [1 2 3 0 0 0; 1 2 3 0 0 0], 50), 'tcp: zero direction', ...
                 'cncrot_machine_tcp_inverse', 'row 1', 'must not be zero');
  expect_error('cncrot:badSize', @() cncrot_machine_tcp_inverse(ac, [1 2 3 0 0 1], 50, [0 0 0]), 'tcp: previous of 3');
  expect_error('cncrot:outOfTravel', @() cncrot_machine_tcp_inverse([1 1 0 0 0 0 100 -10 10 0 0 0; 1 0 0 1 0 0 0 0 0 0 0 0], ...
                                                                  [10 0 0 0.5 0 sqrt(3)/2], 50), 'tcp: travel');
  % Five-axis programs: the same worked example from each dialect's blocks, equal to the
  % transformation of the CL row bit for bit (the same library calls).
  progs = {{'sinumerik', {'TRAORI', 'G1 X10 Y0 Z0 A3=0.5 B3=0 C3=0.8660254037844386', 'G2 X0 Y10 CR=10'}}, ...
           {'heidenhain', {'1 M128', '2 LN X+10 Y+0 Z+0 TX+0.5 TY+0 TZ+0.8660254037844386', '3 CC X+0 Y+0'}}, ...
           {'fanuc', {'G43.5 H1', 'G1 X10. Y0. Z0. I0.5 J0. K0.8660254037844386', 'M30'}}};
  for k = 1:numel(progs)
    [Pp, kinds] = cncrot_tool_path_lines(progs{k}{1}, progs{k}{2});
    check(isequal(size(Pp), [3 9]) && all(isnan(Pp(1, :))) && isequal(Pp(2, 1:3), [10 0 0]) ...
          && max(abs(Pp(2, 4:6) - [0.5 0 sqrt(3)/2])) < 1e-15 && all(isnan(Pp(2, 7:9))), ['tool path: CL of ' progs{k}{1}]);
    check(isequal(kinds{2}, 'point') && isequal(kinds{1}, 'applied'), ['tool path: kinds of ' progs{k}{1}]);
    Ap = cncrot_tool_path_lines(progs{k}{1}, progs{k}{2}, ac, 50, [0 0 0 20 80 0]);
    check(isequal(Ap(2, :), cncrot_machine_tcp_inverse(ac, Pp(2, 1:6), 50, [0 0 0 20 80 0])) && all(isnan(Ap(3, :))), ...
          ['tool path: axes of ' progs{k}{1}]);
  end
  Ax = cncrot_tool_path_lines('fanuc', {'G43.4 H1', 'G1 X10. Y0. Z0. A30. C90.'}, ac, 50);
  check(max(abs(Ax(2, :) - want)) < 1e-9, 'tool path: rotary positions by letter');
  expect_message('cncrot:badArgument', @() cncrot_tool_path_lines('fanuc', {'G43.4 H1'}, ac, 50, zeros(1, 6), 'minus', 3), ...
                 'tool_path_lines: ref beyond the axes', 'cncrot_tool_path_lines', 'argument 7 (ref)', 'got 3');
  [~, kinds] = cncrot_tool_path_lines('heidenhain', {'1 C X+5 Y+0 DR+', '2 TOOL CALL 1 Z'});
  check(isequal(kinds, {'not followed'; 'passed'}), 'tool path: not followed, passed');
  expect_message('cncrot:badArgument', @() cncrot_tool_path_lines('fanuc', {'G43.5 H1', 'G1 I0 J0 K0'}), 'tool path: zero direction', ...
                 'cncrot_tool_path_lines', 'line 2');
  expect_error('cncrot:notAvailable', @() cncrot_tool_path_lines('twincat', 'G1 X1'), 'tool path: TwinCAT');
  fid = fopen(cases_file, 'r');
  check(fid >= 0, 'cases file');
  n = 0;
  bits = @(x) lower(num2hex(x));
  while true
    line = fgetl(fid);
    if ~ischar(line), break; end
    t = strsplit(strtrim(line), ' ');
    h = @(k) hex2num(t{k});
    hv = @(k, m) arrayfun(@(j) hex2num(t{j}), k:k + m - 1);
    same = @(x, k) all(arrayfun(@(j) strcmp(bits(x(j)), lower(t{k + j - 1})), 1:numel(x)));
    unhex = @(x) char(sscanf(x, '%2x').');
    switch t{1}
      case 'M'
        R = cncrot_matrix(str2double(t{2}), str2double(t{3}), hv(4, 3));
        check(same(reshape(R.', 1, 9), 7), ['parity ' line]);
      case 'A'
        M = reshape(hv(4, 9), 3, 3).';
        [a, st] = cncrot_angles(str2double(t{2}), str2double(t{3}), M);
        check(same(a, 13) && st == str2double(t{16}), ['parity ' line]);
      case 'C'
        [a, st] = cncrot_convert(str2double(t{2}), str2double(t{3}), hv(4, 3), str2double(t{7}), str2double(t{8}));
        check(same(a, 9) && st == str2double(t{12}), ['parity ' line]);
      case 'Y'
        p = hv(6, 9);
        g = cycle600(str2double(t{2}), 'UFK600', 1, str2double(t{3}), p(1), p(2), p(3), p(4), p(5), p(6), ...
                     p(7), p(8), p(9), str2double(t{4}), str2double(t{5}), 0, 0, 0);
        check(same([g.CYC600_2 g.CYC600_3 g.CYC600_4], 15) && same(reshape(g.frame.', 1, 16), 18) ...
              && g.CYC600_5 == str2double(t{34}) && g.CYC600_6 == str2double(t{35}), ['parity ' line]);
      case 'F'
        cnt = str2double(t{4});
        F = cncrot_form_frame(str2double(t{2}), str2double(t{3}), hv(5, cnt));
        check(same(reshape(F.', 1, 16), 5 + cnt), ['parity ' line]);
      case 'V'
        cnt = str2double(t{4});
        F = reshape(hv(5, 16), 4, 4).';
        [w, st] = cncrot_form_values(str2double(t{2}), str2double(t{3}), F);
        check(same(w, 21) && st == str2double(t{21 + cnt}), ['parity ' line]);
      case 'PF'
        [a, F] = cncrot_probe_flange(hv(2, 3), hv(5, 3), hv(8, 3), hv(11, 3));
        check(same(a, 14) && same(reshape(F.', 1, 16), 17), ['parity ' line]);
      case 'PP'
        [F, fl, rm] = cncrot_probe_plane(reshape(hv(2, 15), 3, 5).');
        check(same(reshape(F.', 1, 16), 17) && same([fl rm], 33), ['parity ' line]);
      case 'W'
        [l, st] = cncrot_program_write(str2double(t{2}), unhex(t{4}), reshape(hv(5, 16), 4, 4).', str2double(t{3}));
        check(strcmp(l, unhex(t{21})) && st == str2double(t{22}), ['parity ' line]);
      case 'T'
        cnt = str2double(t{6});
        src = cellfun(unhex, t(7:6 + cnt), 'UniformOutput', false);
        want = t(7 + cnt:6 + 2 * cnt);
        for k = 1:cnt
          if strcmp(want{k}, '-'), want{k} = ''; else, want{k} = unhex(want{k}); end
        end
        got = cncrot_program_translate(str2double(t{2}), src, str2double(t{3}), unhex(t{5}), str2double(t{4}));
        check(isequal(got(:).', want), ['parity ' line]);
      case 'L'
        F = cncrot_program_lines(str2double(t{2}), unhex(t{3}));
        check(same(reshape(F.', 1, 16), 4), ['parity ' line]);
      case 'KP'
        F = cncrot_program_lines(str2double(t{3}), unhex(t{4}), [], machines{str2double(t{2}) + 1});
        check(same(reshape(F.', 1, 16), 5), ['parity ' line]);
      case 'KF'
        F = cncrot_machine_forward(machines{str2double(t{2}) + 1}, hv(3, 3));
        check(same(reshape(F.', 1, 16), 6), ['parity ' line]);
      case 'KI'
        cnt = str2double(t{19});
        [S, fr] = cncrot_machine_inverse(machines{str2double(t{2}) + 1}, reshape(hv(3, 16), 4, 4).');
        sol = hv(20, 6);
        check(size(S, 1) == cnt && same(reshape(S.', 1, []), 20) && fr == (str2double(t{26}) == 2), ['parity ' line]);
      case 'KC'
        [a, R, res, st] = cncrot_machine_choose(machines{str2double(t{2}) + 1}, reshape(hv(5, 16), 4, 4).', ...
                                                hv(21, 3), str2double(t{3}), str2double(t{4}));
        check(same(a, 24) && same(res, 27) && same(reshape(R.', 1, 16), 30) && st == str2double(t{46}), ['parity ' line]);
      case 'KT'
        P = cncrot_machine_tcp_forward(machines{str2double(t{2}) + 1}, hv(3, 6), h(9));
        [A, st] = cncrot_machine_tcp_inverse(machines{str2double(t{2}) + 1}, reshape(hv(10, 16), 4, 4).', h(9), hv(26, 6));
        check(same(reshape(P.', 1, 16), 10) && same(A, 32) && st == str2double(t{38}), ['parity ' line]);
      case 'KL'
        cl = [hv(3, 3), hv(6, 3)];
        mk = machines{str2double(t{2}) + 1};
        if size(mk, 1) == 3
          prev = hv(26, 6);
          P = cncrot_cl_pose(cl, cncrot_machine_forward(mk, prev(4:6)));
        else
          P = cncrot_cl_pose(cl);
        end
        [A, st] = cncrot_machine_tcp_inverse(mk, cl, h(9), hv(26, 6));
        check(same(reshape(P.', 1, 16), 10) && same(A, 32) && st == str2double(t{38}), ['parity ' line]);
      case 'PE'
        [a, F2] = cncrot_probe_edge(reshape(hv(2, 16), 4, 4).', hv(18, 3), hv(21, 3));
        check(same(a, 24) && same(reshape(F2.', 1, 16), 25), ['parity ' line]);
    end
    n = n + 1;
  end
  fclose(fid);
  check(n >= 200, sprintf('parity cases read: %d', n));
  fprintf('octave: %d passed, %d failed\n', passed, failed);
  if failed > 0
    error('cncrot:testsFailed', '%d MATLAB/Octave tests failed', failed);
  end
end
