function build_mex(prefix, outdir)
% BUILD_MEX  Builds the cncrot MEX functions, in MATLAB or GNU Octave.
%   BUILD_MEX() finds the library by itself, in this order: the environment variable
%   CNCROT_PREFIX; an installation this folder belongs to (PREFIX/share/cncrot/matlab, as
%   install.sh puts it: PREFIX/lib/libcncrot.a, PREFIX/include/cncrot/cncrot.h); the
%   repository this folder belongs to, after `cargo build --release` (in
%   CARGO_TARGET_DIR/release when that variable is set, else target/release); pkg-config.
%   BUILD_MEX(PREFIX) uses the installation under PREFIX.
%   BUILD_MEX(PREFIX, OUTDIR) writes the MEX files to OUTDIR (default: this folder); add
%   OUTDIR and this folder (for the help texts) to the MATLAB path.
%   On Windows it takes PREFIX/lib/cncrot.lib (MSVC) or PREFIX/lib/libcncrot.a (MinGW-w64)
%   of the real-time build (docs/windows.md).
%   MATLAB: mex -R2018a (interleaved complex API); Octave: mkoctfile --mex with
%   MX_HAS_INTERLEAVED_COMPLEX=1, which declares the same API, and CNCROT_OCTAVE.
%   It prints the library it links, one line per MEX file built, and a summary.
%
%   See also CONTENTS, CNCROT_CONVERT.
  here = fileparts(mfilename('fullpath'));
  if nargin < 1
    prefix = '';
  end
  if nargin < 2 || isempty(outdir)
    outdir = here;
  end
  [lib, incdir] = find_library(here, prefix);
  inc = ['-I' incdir];
  if ispc
    % Windows: the real-time build (install.sh --realtime --target ...) needs nothing but
    % the C runtime's memory functions, which every compiler links anyway.
    syslibs = {};
  else
    syslibs = {'-lm', '-lpthread', '-ldl'};
  end
  names = {'cncrot_matrix', 'cncrot_angles', 'cncrot_convert', 'cycle600', 'cncrot_form_frame', 'cncrot_form_values', 'cncrot_probe_flange', 'cncrot_probe_plane', 'cncrot_probe_edge', 'cncrot_program_lines', 'cncrot_program_write', 'cncrot_program_translate', 'cncrot_program_axes', 'cncrot_machine_forward', 'cncrot_machine_inverse', 'cncrot_machine_choose', 'cncrot_machine_tcp_forward', 'cncrot_machine_tcp_inverse', 'cncrot_cl_pose', 'cncrot_tool_path_lines'};
  octave = exist('OCTAVE_VERSION', 'builtin') ~= 0;
  if octave
    ext = 'mex';
  else
    ext = mexext();
  end
  fprintf('build_mex: library %s\n', lib);
  for k = 1:numel(names)
    src = fullfile(here, 'src', [names{k} '.c']);
    target = fullfile(outdir, [names{k} '.' ext]);
    if octave
      % CNCROT_OCTAVE: read inputs with the accessor that Octave's compact ranges, diagonal
      % and permutation matrices support, and leave the function's name out of error
      % messages, which Octave puts there itself (see src/gateway.h).
      [out, status] = mkoctfile('--mex', '-DMX_HAS_INTERLEAVED_COMPLEX=1', '-DCNCROT_OCTAVE', inc, src, lib, ...
                                syslibs{:}, '-o', target);
      if status ~= 0
        error('cncrot:build', 'mkoctfile failed for %s: %s', names{k}, out);
      end
    else
      mex('-R2018a', '-silent', inc, src, lib, syslibs{:}, '-outdir', outdir);
    end
    fprintf('  built %-24s %s\n', names{k}, target);
  end
  fprintf('build_mex: %d MEX functions built in %s\n', numel(names), outdir);
  % The session saw only the .m help files when it started: look again, so that the new
  % MEX files are the ones called.
  rehash;
end

function [lib, incdir] = find_library(here, prefix)
% The static library and the folder of cncrot.h: the first place that has both.
  places = {};
  if ~isempty(prefix)
    places = {prefix};
  elseif ~isempty(getenv('CNCROT_PREFIX'))
    places = {getenv('CNCROT_PREFIX')};
  else
    installed = fileparts(fileparts(fileparts(here)));   % PREFIX/share/cncrot/matlab
    places = {installed, fileparts(here)};                % then the repository
    [status, libdir] = system('pkg-config --variable=libdir cncrot');
    if status == 0
      places{end + 1} = fileparts(strtrim(libdir));
    end
  end
  % A repository's build: cargo writes to CARGO_TARGET_DIR when it is set (relative to the
  % repository, where the build is run), to target/ otherwise.
  target = getenv('CARGO_TARGET_DIR');
  for k = 1:numel(places)
    p = places{k};
    if isempty(target)
      built = fullfile(p, 'target', 'release', 'libcncrot.a');
    elseif is_absolute(target)
      built = fullfile(target, 'release', 'libcncrot.a');
    else
      built = fullfile(p, target, 'release', 'libcncrot.a');
    end
    candidates = {fullfile(p, 'lib', 'libcncrot.a'), fullfile(p, 'include', 'cncrot'); ...
                  built, fullfile(p, 'include')};
    if ispc
      % MSVC (cncrot.lib, install.sh --realtime --target x86_64-pc-windows-msvc) first,
      % then MinGW-w64 (libcncrot.a, --target x86_64-pc-windows-gnu).
      candidates = [{fullfile(p, 'lib', 'cncrot.lib'), fullfile(p, 'include', 'cncrot')}; candidates];
    end
    for c = 1:size(candidates, 1)
      if exist(candidates{c, 1}, 'file') && exist(fullfile(candidates{c, 2}, 'cncrot.h'), 'file')
        lib = candidates{c, 1};
        incdir = candidates{c, 2};
        return;
      end
    end
  end
  error('cncrot:build', ['no cncrot library found in %s: install it (install.sh), ' ...
        'or run cargo build --release in the repository, or give its prefix: ' ...
        'build_mex(PREFIX)'], strjoin(places, ', '));
end

function yes = is_absolute(p)
% Whether a path is absolute (/..., \\server\..., C:\...).
  yes = ~isempty(p) && (p(1) == '/' || p(1) == '\' || (numel(p) >= 2 && p(2) == ':'));
end
