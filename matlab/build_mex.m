function build_mex()
% BUILD_MEX  Builds the cncrot MEX functions into this folder, in MATLAB or GNU Octave.
%   Needs the static library: run `cargo build --release` in the repository first.
%   MATLAB: mex -R2018a (interleaved complex API); Octave: mkoctfile --mex with
%   MX_HAS_INTERLEAVED_COMPLEX=1, which declares the same API, and CNCROT_OCTAVE.
  here = fileparts(mfilename('fullpath'));
  root = fileparts(here);
  lib = fullfile(root, 'target', 'release', 'libcncrot.a');
  if ~exist(lib, 'file')
    error('cncrot:build', 'missing %s: run cargo build --release first', lib);
  end
  inc = ['-I' fullfile(root, 'include')];
  names = {'cncrot_matrix', 'cncrot_angles', 'cncrot_convert', 'cycle600', 'cncrot_form_frame', 'cncrot_form_values', 'cncrot_probe_flange', 'cncrot_probe_plane', 'cncrot_probe_edge', 'cncrot_program_lines', 'cncrot_program_write', 'cncrot_machine_forward', 'cncrot_machine_inverse', 'cncrot_machine_choose'};
  for k = 1:numel(names)
    src = fullfile(here, 'src', [names{k} '.c']);
    if exist('OCTAVE_VERSION', 'builtin')
      % CNCROT_OCTAVE: read inputs with the accessor that Octave's compact ranges, diagonal
      % and permutation matrices support (see src/gateway.h).
      [out, status] = mkoctfile('--mex', '-DMX_HAS_INTERLEAVED_COMPLEX=1', '-DCNCROT_OCTAVE', inc, src, lib, ...
                                '-lm', '-lpthread', '-ldl', '-o', fullfile(here, [names{k} '.mex']));
      if status ~= 0
        error('cncrot:build', 'mkoctfile failed for %s: %s', names{k}, out);
      end
    else
      mex('-R2018a', inc, src, lib, '-lm', '-lpthread', '-ldl', '-outdir', here);
    end
  end
end
