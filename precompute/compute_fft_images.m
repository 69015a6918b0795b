function compute_fft_images(heightsFile, dHum, termCnt, outDir)
% COMPUTE_FFT_IMAGES  An independent re-statement of the thesis' precompute (003 Algorithm 1), used by
% diffract's tests to check its thesis-format writer; it is not part of the program.
%
%   heightsFile: text matrix of the MEAN-SUBTRACTED heights in micrometres (row 1 = first row of the patch)
%   dHum:        pixel size in micrometres (extrema.txt stores it in metres)
%   termCnt:     highest Taylor order N; writes AmpReIm0.txt .. AmpReIm<N>.txt and extrema.txt into outDir
%
% Recipe, as the original script: rotate the heights by -90 degrees, DFT_t = fftshift(ifft2((1j*h)^t)), rotate
% each output channel by +90 degrees, normalise Re and Im separately to [0, 1] (eq. 1.1, with the 1e-35 guards),
% write big-endian: int32 width, int32 height, then per row from the bottom up, per column, (Re, Im, 0.5) float32.
  patchImg = load(heightsFile);
  patchImg = rot90(patchImg, -1);
  ext = fopen(fullfile(outDir, 'extrema.txt'), 'w');
  for t = 0:termCnt
    fftTerm = fftshift(ifft2(power(1j * patchImg, t)));
    re = rot90(real(fftTerm), 1);
    im = rot90(imag(fftTerm), 1);
    [reN, reMin, reRange] = normalise(re);
    [imN, imMin, imRange] = normalise(im);
    imOut = cat(3, reN, imN, 0.5 * ones(size(reN)));
    [H, W] = size(reN);
    fid = fopen(fullfile(outDir, sprintf('AmpReIm%d.txt', t)), 'w');
    fwrite(fid, [W H], 'int32', 0, 'ieee-be');
    % channel fastest, then column, then row; rows from the bottom up
    fwrite(fid, permute(flipud(imOut), [3 2 1]), 'float32', 0, 'ieee-be');
    fclose(fid);
    fprintf(ext, '%36.35f\n', [reMin imMin 0 dHum*1e-6 reRange imRange 1 dHum*1e-6]);
  end
  fclose(ext);
end

function [v, m, r] = normalise(x)
  m = min(x(:));
  if abs(m) < 1e-35
    m = 0;
  end
  r = max(x(:)) - m;
  if r < 1e-35
    r = 1;
  end
  v = (x - m) / r;
end
