#include "Net/Private/TokenCheck.h"

namespace proxima::detail
{

bool tokenAccepted(const grpc::ServerContext& context, const std::string& token)
{
  if (token.empty())
  {
    return true;
  }
  const auto& metadata = context.client_metadata();
  const auto found = metadata.find(kTokenMetadata);
  if (found == metadata.end() || found->second.size() != token.size())
  {
    return false;
  }
  // Every character compared, whatever differs first: no timing hint of a partial match.
  unsigned difference = 0;
  for (std::size_t i = 0; i < token.size(); ++i)
  {
    difference |=
      static_cast<unsigned char>(found->second.data()[i]) ^ static_cast<unsigned char>(token[i]);
  }
  return difference == 0;
}

} // namespace proxima::detail
