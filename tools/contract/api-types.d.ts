// The types the explorer's modules import (JSDoc `import('…/api-types')`): those generated from the
// service's document by openapi-typescript (`make contract`), under a name of their own.
export type { components, paths } from './openapi';
