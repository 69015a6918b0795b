#!/usr/bin/env bash
# The snake scenes with the scalar model's orders (their default) and with the rigorous orders (--orders rigorous:
# each lobe of the key light weighted by Maxwell's equations on the patch's average ridge, docs/design/rigorous.md), the
# whole frame and a closer view (--distance 1.1), into docs/images/rigorous-snake-*.png, and `measure` of each into
# docs/measurements/rigorous-snakes.md. The first rigorous render of each patch solves its table of rigorous orders (about 12
# minutes on 2 cores), which the disk cache keeps; the rest takes a few minutes. From anywhere:
# bash docs/measurements/rigorous-snakes.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
out=docs/measurements/rigorous-snakes.md
mkdir -p docs/images out
for species in elaphe xenopeltis; do
    scene=assets/scenes/snake-$species.json
    for orders in scalar rigorous; do
        ./diffract render "$scene" --orders "$orders" -q -o "docs/images/rigorous-snake-$species-$orders.png"
        ./diffract render "$scene" --orders "$orders" -q --distance 1.1 \
            -o "docs/images/rigorous-snake-$species-$orders-close.png"
        ./diffract measure "$scene" --orders "$orders" -q > "out/rigorous-snake-$species-$orders.txt"
    done
done
{
    echo "# The snakes with the scalar and with the rigorous orders"
    echo
    echo "Made by \`bash docs/measurements/rigorous-snakes.sh\`: the default snake scenes as they ship (the lobes method with the"
    echo "scalar model's orders and Rayleigh-Rice's gain, keratin n = 1.56) and with \`--orders rigorous\`, which"
    echo "weights each lobe of the key light by its order's ratio of rigorous to scalar efficiency, solved on the"
    echo "patch's average ridge ([rigorous.md](../design/rigorous.md#the-rigorous-orders-on-the-fast-path)); the environment's"
    echo "lights read a baked table and keep the scalar orders."
    echo
    for species in elaphe xenopeltis; do
        echo "## snake-$species.json"
        echo
        echo "| scalar orders (the default) | rigorous orders |"
        echo "| --- | --- |"
        echo "| ![](../images/rigorous-snake-$species-scalar.png) | ![](../images/rigorous-snake-$species-rigorous.png) |"
        echo "| ![](../images/rigorous-snake-$species-scalar-close.png) | ![](../images/rigorous-snake-$species-rigorous-close.png) |"
        echo
        echo "\`diffract measure\` (saturated structural colour, its patches and hue bins):"
        echo
        echo '```'
        for orders in scalar rigorous; do
            echo "--orders $orders:"
            cat "out/rigorous-snake-$species-$orders.txt"
        done
        echo '```'
        echo
    done
} > "$out"
echo "wrote $out"
