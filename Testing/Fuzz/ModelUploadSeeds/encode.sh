#!/usr/bin/env bash
# Encodes the seed uploads of FuzzModelUpload (text protobuf, readable and editable here) into its
# seed corpus, Testing/Fuzz/Corpus/FuzzModelUpload/NAME.bin, with protoc. Run after editing a seed.
set -euo pipefail
cd "$(dirname "$0")"
proto=../../../Library/Net
for seed in *.txtpb; do
  protoc --encode=proxima.net.ModelUploadSequence -I "$proto" "$proto/proxima_haptic.proto" \
    < "$seed" > "../Corpus/FuzzModelUpload/${seed%.txtpb}.bin"
done
