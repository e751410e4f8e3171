#!/usr/bin/env bash
# Encodes the seed requests of FuzzRunRequest (text protobuf, readable and editable here) into its
# seed corpus, Testing/Fuzz/Corpus/FuzzRunRequest/NAME.bin, with protoc. Run after editing a seed.
set -euo pipefail
cd "$(dirname "$0")"
proto=../../../Library/Net
for seed in *.txtpb; do
  protoc --encode=proxima.net.RunRequest -I "$proto" "$proto/proxima_remote.proto" < "$seed" \
    > "../Corpus/FuzzRunRequest/${seed%.txtpb}.bin"
done
