#pragma once
// A Gaussian of standard deviation sigma approximated by three extended box
// filters in a row (Gwosdek, Grewenig, Bruhn and Weickert 2011, "Theoretical
// foundations of Gaussian convolution by extended box filtering"). A box of
// radius r extended by weight alpha on the two samples just outside it,
//     [alpha, 1, ..., 1, alpha]  (2r + 1 ones),
// has variance (r (r + 1) (2r + 1) / 3 + 2 alpha (r + 1)^2) / (2r + 1 + 2 alpha),
// so any variance is reached exactly, not only the few an integer box width
// gives. Three of them make a piecewise-quadratic kernel of variance sigma^2
// that reaches 3 (r + 1) ~ 3 sigma + 1.5 pixels, like the Gaussian truncated
// at 3 sigma it replaces, and each costs the same whatever sigma is: a running
// sum adds the sample entering the box and subtracts the one leaving it.
#include <array>
#include <vector>

namespace darkroom::passes {

struct ExtendedBox {
    int radius = 0;      // 2 radius + 1 samples of weight 1 ...
    double alpha = 0.0;  // ... and one of weight alpha on each side (0 <= alpha < 1)
};

constexpr int kBoxes = 3;
using BoxCascade = std::array<ExtendedBox, kBoxes>;

// The cascade of variance sigma^2 (sigma >= 0, pixels). Beyond the image a
// wider kernel changes little but the cost: sigma is capped at `imageSize`
// (the larger side of the image).
BoxCascade boxCascade(double sigma, int imageSize);

// How far outside the axis the output of box k (0, 1, 2) is needed so that
// the cascade equals one convolution with its whole kernel (the later boxes
// reach that far); the input of box 0 is the axis itself.
int cascadeMargin(const BoxCascade& c, int k);

// The cascade's weights at offsets -reach .. reach (reach = the sum of
// radius + 1 over the boxes), not normalised: for tests and documentation.
std::vector<double> cascadeWeights(const BoxCascade& c);

}  // namespace darkroom::passes
