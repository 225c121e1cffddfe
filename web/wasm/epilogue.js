
export default createDrmDecoderModule;
