#pragma once
// The histogram variant's bins: Histogram_Bins (1 to 256) equal bins of log2(Y) over
// [Histogram_Min_Log2, Histogram_Max_Log2]; a Y below the range, 0 included, counts in the first
// bin and one above it in the last, so every pixel is counted. Bin counts travel four to a texel:
// texel g of a row holds bins 4g .. 4g + 3, and texel HISTOGRAM_STATS_TEXEL (the peak Y, the pixel
// count).

uniform int Histogram_Bins;
uniform float Histogram_Min_Log2;
uniform float Histogram_Max_Log2;

const int HISTOGRAM_MAX_BINS = 256;
const int HISTOGRAM_STATS_TEXEL = HISTOGRAM_MAX_BINS / 4;
const int HISTOGRAM_TILES = 16;  // Input is cut into 16 x 16 tiles, one row of partial counts each

int histogramBins() { return clamp(Histogram_Bins, 1, HISTOGRAM_MAX_BINS); }

// Guards an empty or reversed range (Min >= Max): every pixel then falls in one end bin.
float histogramBinWidthLog2() { return max(Histogram_Max_Log2 - Histogram_Min_Log2, 1e-6) / float(histogramBins()); }

int histogramBin(float y) {
    if (!(y > 0.0)) return 0;
    float position = floor((log2(y) - Histogram_Min_Log2) / histogramBinWidthLog2());
    return int(clamp(position, 0.0, float(histogramBins() - 1)));
}

float histogramBinCentreLog2(int bin) { return Histogram_Min_Log2 + (float(bin) + 0.5) * histogramBinWidthLog2(); }
