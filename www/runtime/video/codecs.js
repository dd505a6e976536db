// What the video saving uses of mediabunny (WebCodecs muxing into MP4 and WebM) and gifenc
// (animated GIF): bundled by `make www` (esbuild, tree-shaken, minified: about 60 KB gzipped)
// into www/vendor/codecs.js, which www/video/encode.js imports only when a video is saved.
export { Output, Mp4OutputFormat, WebMOutputFormat, BufferTarget, CanvasSource, canEncodeVideo, QUALITY_HIGH } from "mediabunny";
export { GIFEncoder, quantize, applyPalette } from "gifenc";
